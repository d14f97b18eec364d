#pragma once
// A linked vertex + fragment program with cached uniform locations.
#include "gl/GlObject.h"
#include "gl/ShaderSource.h"

#include <glm/glm.hpp>
#include <string>
#include <unordered_map>

namespace pb::gl {

class Program {
public:
    // Compiles and links; throws pb::Error with the driver's log mapped to file:line.
    Program(const std::string& vertexName, const std::string& fragmentName,
            const Defines& defines);

    void use() const { glUseProgram(id_.id()); }
    GLint location(const std::string& uniform) const;
    bool has(const std::string& uniform) const { return location(uniform) >= 0; }

    // Setters act on the currently used program; unknown names are ignored (the compiler may
    // strip unused uniforms, differently per variant).
    void set(const std::string& n, int v) const;
    void set(const std::string& n, float v) const;
    void set(const std::string& n, const glm::vec2& v) const;
    void set(const std::string& n, const glm::vec3& v) const;
    void set(const std::string& n, const glm::vec4& v) const;
    void set(const std::string& n, const glm::ivec2& v) const;
    void set(const std::string& n, const glm::ivec3& v) const;
    void set(const std::string& n, const glm::mat3& v) const;
    void set(const std::string& n, const glm::mat4& v) const;

    const std::string& label() const { return label_; }

private:
    ProgramId id_;
    std::string label_;
    mutable std::unordered_map<std::string, GLint> locations_;
};

} // namespace pb::gl
