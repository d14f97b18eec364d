#include "gl/Program.h"

#include "gl/DebugLabels.h"
#include "core/Error.h"

#include <glm/gtc/type_ptr.hpp>
#include <vector>

namespace pb::gl {

namespace {

std::string shaderLog(GLuint s) {
    GLint len = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    std::string log(size_t(len > 0 ? len : 1), '\0');
    glGetShaderInfoLog(s, len, nullptr, log.data());
    return log.c_str();
}

ShaderId compile(GLenum stage, const std::string& name, const Defines& defines) {
    AssembledSource src = assembleShader(name, defines);
    ShaderId s(glCreateShader(stage));
    const char* text = src.text.c_str();
    glShaderSource(s.id(), 1, &text, nullptr);
    glCompileShader(s.id());
    GLint ok = 0;
    glGetShaderiv(s.id(), GL_COMPILE_STATUS, &ok);
    if (!ok)
        throw Error("shader " + name + " [" + definesKey(defines) + "] failed to compile:\n" +
                    annotateShaderLog(shaderLog(s.id()), src.files));
    return s;
}

} // namespace

Program::Program(const std::string& vertexName, const std::string& fragmentName,
                 const Defines& defines)
    : label_(vertexName + "+" + fragmentName + " [" + definesKey(defines) + "]") {
    ShaderId vs = compile(GL_VERTEX_SHADER, vertexName, defines);
    ShaderId fs = compile(GL_FRAGMENT_SHADER, fragmentName, defines);
    id_ = ProgramId(glCreateProgram());
    glAttachShader(id_.id(), vs.id());
    glAttachShader(id_.id(), fs.id());
    glLinkProgram(id_.id());
    glDetachShader(id_.id(), vs.id());
    glDetachShader(id_.id(), fs.id());
    GLint ok = 0;
    glGetProgramiv(id_.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(id_.id(), GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(len > 0 ? len : 1), '\0');
        glGetProgramInfoLog(id_.id(), len, nullptr, log.data());
        throw Error("program " + label_ + " failed to link:\n" + log.c_str());
    }
    labelObject(GL_PROGRAM, id_.id(), label_);
}

GLint Program::location(const std::string& uniform) const {
    auto it = locations_.find(uniform);
    if (it != locations_.end()) return it->second;
    GLint loc = glGetUniformLocation(id_.id(), uniform.c_str());
    locations_.emplace(uniform, loc);
    return loc;
}

// clang-format off
void Program::set(const std::string& n, int v) const { if (GLint l = location(n); l >= 0) glUniform1i(l, v); }
void Program::set(const std::string& n, float v) const { if (GLint l = location(n); l >= 0) glUniform1f(l, v); }
void Program::set(const std::string& n, const glm::vec2& v) const { if (GLint l = location(n); l >= 0) glUniform2fv(l, 1, glm::value_ptr(v)); }
void Program::set(const std::string& n, const glm::vec3& v) const { if (GLint l = location(n); l >= 0) glUniform3fv(l, 1, glm::value_ptr(v)); }
void Program::set(const std::string& n, const glm::vec4& v) const { if (GLint l = location(n); l >= 0) glUniform4fv(l, 1, glm::value_ptr(v)); }
void Program::set(const std::string& n, const glm::ivec2& v) const { if (GLint l = location(n); l >= 0) glUniform2iv(l, 1, glm::value_ptr(v)); }
void Program::set(const std::string& n, const glm::ivec3& v) const { if (GLint l = location(n); l >= 0) glUniform3iv(l, 1, glm::value_ptr(v)); }
void Program::set(const std::string& n, const glm::mat3& v) const { if (GLint l = location(n); l >= 0) glUniformMatrix3fv(l, 1, GL_FALSE, glm::value_ptr(v)); }
void Program::set(const std::string& n, const glm::mat4& v) const { if (GLint l = location(n); l >= 0) glUniformMatrix4fv(l, 1, GL_FALSE, glm::value_ptr(v)); }
// clang-format on

} // namespace pb::gl
