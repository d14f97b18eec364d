#include "gl/ShaderSource.h"

#include "core/Error.h"

#include <regex>
#include <sstream>

namespace pb::shaders {
const std::map<std::string, std::string>& embeddedSources(); // generated at build time
}

namespace pb::gl {

std::string definesKey(const Defines& defines) {
    std::string key;
    for (const auto& [k, v] : defines) {
        if (!key.empty()) key += ';';
        key += v.empty() ? k : k + "=" + v;
    }
    return key;
}

namespace {

const char* kPrelude = "precision highp float;\n"
                       "precision highp int;\n"
                       "precision highp sampler2D;\n"
                       "precision highp sampler2DArray;\n"
                       "precision highp sampler2DShadow;\n";

const std::string& sourceOf(const std::string& name) {
    const auto& all = pb::shaders::embeddedSources();
    auto it = all.find(name);
    if (it == all.end()) throw Error("shader source '" + name + "' is not in shaders/");
    return it->second;
}

void expand(const std::string& name, std::vector<std::string>& files, std::ostringstream& out,
            int depth) {
    if (depth > 8) throw Error("shader " + name + ": #include nested too deeply (a cycle?)");
    int fileIndex = int(files.size());
    files.push_back(name);
    std::istringstream in(sourceOf(name));
    std::string line;
    int lineNo = 0;
    out << "#line 1 " << fileIndex << "\n";
    static const std::regex includeRe(R"(^\s*#\s*include\s+\"([^\"]+)\"\s*$)");
    std::smatch m;
    while (std::getline(in, line)) {
        ++lineNo;
        if (std::regex_match(line, m, includeRe)) {
            expand(m[1].str(), files, out, depth + 1);
            out << "#line " << lineNo + 1 << " " << fileIndex << "\n";
        } else {
            out << line << "\n";
        }
    }
}

} // namespace

AssembledSource assembleShader(const std::string& name, const Defines& defines) {
    AssembledSource result;
    std::ostringstream out;
    // GLSL_ES_310: the variant uses a GLSL ES 3.10 feature (atomic counters, early-test
    // layouts). Both stages of a program get the same defines, so both get the same version,
    // which ES linkers require.
    out << (defines.count(kGlslEs310Define) ? "#version 310 es\n" : "#version 300 es\n")
        << kPrelude;
    for (const auto& [k, v] : defines)
        out << "#define " << k << (v.empty() ? "" : " " + v) << "\n";
    expand(name, result.files, out, 0);
    result.text = out.str();
    return result;
}

std::string annotateShaderLog(const std::string& log, const std::vector<std::string>& files) {
    // Mesa: "0:12(5): error: ..."; others: "ERROR: 0:12: ...". Map the source-string number.
    static const std::regex re(R"((\d+):(\d+)(\(\d+\))?:)");
    std::string result;
    std::sregex_iterator it(log.begin(), log.end(), re), end;
    size_t last = 0;
    for (; it != end; ++it) {
        size_t idx = std::stoul((*it)[1].str());
        result += log.substr(last, size_t(it->position()) - last);
        if (idx < files.size())
            result += files[idx] + ":" + (*it)[2].str() + ":";
        else
            result += it->str();
        last = size_t(it->position() + it->length());
    }
    result += log.substr(last);
    return result;
}

} // namespace pb::gl
