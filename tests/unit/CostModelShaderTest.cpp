// The cost model's fetch structure per variant (costmodel/GiVariant.h) against the shader
// source it models: shaders/common_ddgi.glsl and gi_ddgi_apply.frag are read, the variant's
// #ifdef branches kept, and the texture fetches of every 8-probe loop of ddgiSample (through
// ddgiProbeWeight / ddgiProbeIrradiance), the corner order of ddgiCorner and the GBuffer reads
// of the apply shader extracted. A fetch added to or removed from the shader, a loop split or
// fused, or a corner order changed without the model fails here.
#include "costmodel/GiVariant.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

using namespace pb::costmodel;

namespace {

std::string readShader(const std::string& name) {
    std::ifstream in(std::string(PB_SOURCE_DIR) + "/shaders/" + name);
    EXPECT_TRUE(in) << name;
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Keeps the lines a preprocessor with `defines` keeps (#ifdef / #ifndef / #else / #endif).
std::string preprocess(const std::string& src, const std::set<std::string>& defines) {
    std::istringstream in(src);
    std::string line, out;
    std::vector<bool> active{true};
    std::smatch m;
    static const std::regex ifdef(R"(^\s*#\s*(ifdef|ifndef)\s+(\w+))");
    while (std::getline(in, line)) {
        if (std::regex_search(line, m, ifdef)) {
            const bool has = defines.count(m[2]) > 0;
            active.push_back(active.back() && (m[1] == "ifdef" ? has : !has));
        } else if (std::regex_search(line, std::regex(R"(^\s*#\s*else)"))) {
            const bool parent = active[active.size() - 2];
            active.back() = parent && !active.back();
        } else if (std::regex_search(line, std::regex(R"(^\s*#\s*endif)"))) {
            active.pop_back();
        } else if (active.back()) {
            out += line.substr(0, line.find("//")) + "\n"; // comments may name fetches
        }
    }
    return out;
}

// The text between the braces of the block opening at or after `from`.
std::string block(const std::string& src, size_t from) {
    const size_t open = src.find('{', from);
    int depth = 0;
    for (size_t i = open; i < src.size(); ++i) {
        if (src[i] == '{') ++depth;
        if (src[i] == '}' && --depth == 0) return src.substr(open + 1, i - open - 1);
    }
    ADD_FAILURE() << "unbalanced braces";
    return {};
}

std::string functionBody(const std::string& src, const std::string& name) {
    std::smatch m;
    const std::regex def("\\n\\w+\\s+" + name + "\\s*\\(");
    if (!std::regex_search(src, m, def)) {
        ADD_FAILURE() << "no function " << name;
        return {};
    }
    return block(src, size_t(m.position(0)));
}

FetchKind samplerKind(const std::string& sampler) {
    if (sampler == "u_ddgiState") return FetchKind::ProbeState;
    if (sampler == "u_ddgiVisibility") return FetchKind::Visibility;
    if (sampler == "u_ddgiIrradiance") return FetchKind::Irradiance;
    if (sampler == "u_gbuffer_depth") return FetchKind::GBufferDepth;
    if (sampler == "u_gbuffer_normal") return FetchKind::GBufferNormal;
    ADD_FAILURE() << "fetch from an unmodelled sampler " << sampler;
    return FetchKind::GBufferDepth;
}

// Texture fetches (any texture*/texelFetch* builtin) and calls of `helpers`, in text order.
std::vector<FetchKind> fetchesIn(const std::string& text,
                                 const std::map<std::string, std::vector<FetchKind>>& helpers) {
    std::vector<FetchKind> out;
    static const std::regex call(R"(\b(texture\w*|texelFetch\w*|ddgi\w+)\s*\(\s*(\w*))");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), call);
         it != std::sregex_iterator(); ++it) {
        const std::string fn = (*it)[1];
        if (fn.rfind("ddgi", 0) == 0) {
            auto h = helpers.find(fn);
            if (h != helpers.end()) out.insert(out.end(), h->second.begin(), h->second.end());
        } else {
            out.push_back(samplerKind((*it)[2]));
        }
    }
    return out;
}

struct ParsedVariant {
    std::vector<std::vector<FetchKind>> loops;
    std::vector<FetchKind> outsideLoops;
    std::array<std::array<int, 3>, 8> corners{};
};

ParsedVariant parse(const GiVariant& v) {
    std::set<std::string> defines{
        v.loops == pb::profile::GiLoops::Split ? "GI_LOOPS_SPLIT" : "GI_LOOPS_FUSED",
        v.order == pb::profile::GiProbeOrder::SliceFirst ? "GI_ORDER_SLICE_FIRST" : "GI_ORDER_XYZ"};
    const std::string src = preprocess(readShader("common_ddgi.glsl"), defines);
    std::map<std::string, std::vector<FetchKind>> helpers;
    helpers["ddgiProbeWeight"] = fetchesIn(functionBody(src, "ddgiProbeWeight"), {});
    helpers["ddgiProbeIrradiance"] = fetchesIn(functionBody(src, "ddgiProbeIrradiance"), {});
    for (const char* fn : {"ddgiAddProbe", "ddgiCornerWeight", "ddgiFusedCorner", "ddgiSplitWeight",
                           "ddgiSplitTile"})
        helpers[fn] = fetchesIn(functionBody(src, fn), helpers);
    ParsedVariant p;
    std::string body = functionBody(src, "ddgiSample");
    static const std::regex loop(R"(for\s*\(\s*int\s+i\s*=\s*0\s*;\s*i\s*<\s*8\s*;\s*\+\+i\s*\))");
    std::smatch m;
    std::string rest;
    while (std::regex_search(body, m, loop)) {
        const size_t after = size_t(m.position(0) + m.length(0));
        size_t end;
        std::string loopBody;
        if (body.find_first_not_of(" \n\t", after) != std::string::npos &&
            body[body.find_first_not_of(" \n\t", after)] == '{') {
            loopBody = block(body, after);
            end = body.find(loopBody, after) + loopBody.size() + 1;
        } else { // a single statement
            end = body.find(';', after) + 1;
            loopBody = body.substr(after, end - after);
        }
        p.loops.push_back(fetchesIn(loopBody, helpers));
        rest += body.substr(0, size_t(m.position(0)));
        body = body.substr(end);
    }
    // Loops written out (common_ddgi.glsl, ddgiFusedCorner says why): 8 consecutive statements
    // that differ only in their corner, the first argument of a ddgi* call, 0..7 in order, are
    // one loop whose fetches are those of one statement.
    static const std::regex cornerCall(R"(\bddgi\w+\s*\(\s*(\d)\s*,)");
    static const std::regex cornerDigit(R"(\b[0-7]\b)");
    std::string shape;
    std::vector<std::string> group;
    std::vector<int> groupCorners;
    const auto flush = [&] {
        if (group.size() == 8 && groupCorners == std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}) {
            p.loops.push_back(fetchesIn(group.front(), helpers));
        } else {
            EXPECT_TRUE(group.empty()) << "statements with corners 0..7 not a loop: " << group.front();
            for (const std::string& st : group)
                rest += st + ";";
        }
        group.clear();
        groupCorners.clear();
        shape.clear();
    };
    size_t from = 0;
    for (size_t semi; (semi = body.find(';', from)) != std::string::npos; from = semi + 1) {
        std::string statement = body.substr(from, semi - from);
        const size_t first = statement.find_first_not_of(" \n\t");
        statement = first == std::string::npos ? std::string() : statement.substr(first);
        std::smatch c;
        if (!std::regex_search(statement, c, cornerCall)) {
            flush();
            rest += statement + ";";
            continue;
        }
        const std::string its = std::regex_replace(statement, cornerDigit, "K");
        if (its != shape) flush();
        shape = its;
        group.push_back(statement);
        groupCorners.push_back(std::stoi(c[1]));
    }
    flush();
    body = body.substr(from);
    p.outsideLoops = fetchesIn(rest + body, helpers);
    // ddgiCorner: return ivec3(<x>, <y>, <z>) with components "i & 1" or "(i >> s) & 1".
    const std::string corner = functionBody(src, "ddgiCorner");
    static const std::regex comp(R"(\(?\s*i\s*(?:>>\s*(\d))?\s*\)?\s*&\s*1)");
    std::vector<int> shifts;
    for (auto it = std::sregex_iterator(corner.begin(), corner.end(), comp);
         it != std::sregex_iterator(); ++it)
        shifts.push_back((*it)[1].matched ? std::stoi((*it)[1]) : 0);
    EXPECT_EQ(shifts.size(), 3u) << corner;
    for (int i = 0; i < 8 && shifts.size() == 3; ++i)
        for (int a = 0; a < 3; ++a)
            p.corners[size_t(i)][size_t(a)] = (i >> shifts[size_t(a)]) & 1;
    return p;
}

} // namespace

TEST(CostModelShader, EveryVariantsFetchLoopsMatchTheShader) {
    for (const GiVariant& v : allGiVariants()) {
        const ParsedVariant p = parse(v);
        const VariantStructure model = variantStructure(v);
        EXPECT_EQ(p.loops, model.loops) << v.name();
        EXPECT_TRUE(p.outsideLoops.empty()) << v.name() << ": fetches outside the 8-probe loops";
        EXPECT_EQ(p.corners, model.cornerOffsets) << v.name();
        int perProbe = 0;
        for (const auto& l : p.loops)
            perProbe += int(l.size());
        EXPECT_EQ(maxFetchesPerLookup(v), kGBufferFetchesPerLookup + 8 * perProbe) << v.name();
    }
}

TEST(CostModelShader, TheApplyShaderReadsDepthThenNormalAndLooksUpOnce) {
    const std::string src = preprocess(readShader("gi_ddgi_apply.frag"), {});
    const std::string main = functionBody(src, "main");
    const std::vector<FetchKind> f = fetchesIn(main, {});
    EXPECT_EQ(f, (std::vector<FetchKind>{FetchKind::GBufferDepth, FetchKind::GBufferNormal}));
    EXPECT_EQ(int(f.size()), kGBufferFetchesPerLookup);
    std::regex sample(R"(\bddgiSample\s*\()");
    EXPECT_EQ(std::distance(std::sregex_iterator(main.begin(), main.end(), sample),
                            std::sregex_iterator()),
              1);
}

TEST(CostModelShader, TheParserSeesAnAddedFetch) {
    // The check above must be able to fail: one more fetch in a loop changes what it parses.
    std::string src = readShader("common_ddgi.glsl");
    const std::string marker = "vec3 ddgiProbeIrradiance(ivec3 tile, vec2 irrCoord) {";
    ASSERT_NE(src.find(marker), std::string::npos);
    src.insert(src.find(marker) + marker.size(),
               "\n    float extra = texture(u_ddgiVisibility, vec3(0.0)).r;");
    const std::string pre = preprocess(src, {"GI_LOOPS_FUSED", "GI_ORDER_XYZ"});
    const std::vector<FetchKind> irr = fetchesIn(functionBody(pre, "ddgiProbeIrradiance"), {});
    EXPECT_EQ(irr.size(), 2u);
}
