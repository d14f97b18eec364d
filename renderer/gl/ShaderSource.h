#pragma once
// GLSL ES 3.00 sources compiled into the binary (shaders/), assembled for one variant:
//   #version 300 es            (desktop GL takes it through ARB_ES3_compatibility), or
//   #version 310 es            when the defines hold GLSL_ES_310 (needs an ES 3.1 context)
//   precision statements
//   #define block of the variant
//   the file, with #include "x.glsl" expanded from the same source set
#include <map>
#include <string>
#include <vector>

namespace pb::gl {

// Ordered defines: NAME -> value ("" for a plain #define NAME).
using Defines = std::map<std::string, std::string>;

// The define that asks for "#version 310 es" instead of "#version 300 es".
inline constexpr const char* kGlslEs310Define = "GLSL_ES_310";

// A stable text key of a define set ("A=1;B;C=2"), used by the program cache.
std::string definesKey(const Defines& defines);

struct AssembledSource {
    std::string text;
    std::vector<std::string> files; // files[i] is source-string number i in #line directives
};

// Throws pb::Error when `name` or an included file does not exist or includes recurse.
AssembledSource assembleShader(const std::string& name, const Defines& defines);

// Rewrites "0(12) : error ..." style driver messages to "file.frag:12: error ...".
std::string annotateShaderLog(const std::string& log, const std::vector<std::string>& files);

} // namespace pb::gl
