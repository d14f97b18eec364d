// Every combination of the shader-visible profile switches (the SwitchTable rows with a
// #define) compiles and links on egl and osmesa: the apply pass (full-screen and as a volume
// box for gi.multi_volume=stencil), the stencil fill, the point evaluator and the lighting
// variant. Generated from the table, so a new switch is covered without editing this file.
// The programs that take no switch defines (depth copy, counting variant, debug views, SH
// projection) are compiled once per backend. Values the pass does not implement yet are
// counted and reported, not compiled.
#include "gl/GlTestFixture.h"

#include "core/Error.h"
#include "gl/ProgramCache.h"
#include "passes/GiApplyPass.h"
#include "profile/SwitchTable.h"

#include <cstdio>

namespace pb::test {
namespace {

// Every DDGI combination of the shader switches, then each SH technique with each leak mode
// on the defaults: common_sh.glsl reads only GI_TECHNIQUE_* and GI_SH_LEAK_*, and the rest of
// the apply shader is DDGI's, so crossing them with every other switch (9x the programs) would
// compile the same SH code again and again.
std::vector<profile::Profile> allShaderCombinations() {
    std::vector<profile::Profile> out(1);
    for (const profile::SwitchInfo& s : profile::switchTable()) {
        if (s.defineStyle == profile::DefineStyle::HostOnly ||
            s.kind != profile::SwitchKind::Choice || s.key == "gi.technique" ||
            s.key == "gi.sh_leak")
            continue;
        std::vector<profile::Profile> next;
        for (const profile::Profile& p : out)
            for (const std::string& v : s.choices) {
                next.push_back(p);
                next.back().set(s.key, v);
            }
        out = std::move(next);
    }
    for (const char* technique : {"sh_l1", "sh_l2"})
        for (const char* leak : {"none", "weight", "validity_mask"}) {
            profile::Profile p;
            p.set("gi.technique", technique);
            p.set("gi.sh_leak", leak);
            out.push_back(p);
        }
    return out;
}

struct ProgramSpec {
    const char* vertex;
    const char* fragment;
};

// Programs built from the profile's GI defines (the lighting gets the switches only).
constexpr ProgramSpec kGiPrograms[] = {
    {"fullscreen.vert", "gi_ddgi_apply.frag"},
    {"gi_volume_box.vert", "gi_ddgi_apply.frag"},
    {"gi_volume_box.vert", "gi_stencil_fill.frag"},
    {"fullscreen.vert", "gi_ddgi_points.frag"},
};

class GiVariantsTest : public GlBackendTest {};

TEST_P(GiVariantsTest, EveryCombinationCompilesAndLinks) {
    int compiled = 0;
    gl::ProgramCache programs;
    const std::vector<profile::Profile> combinations = allShaderCombinations();
    for (const profile::Profile& p : combinations) {
        gl::Defines lighting;
        for (const auto& [k, v] : profile::shaderDefines(p))
            lighting[k] = v;
        lighting["GI_ENABLED"] = "";
        std::string what;
        for (const auto& c : p.changedSwitches())
            what += " " + c;
        try {
            // Each variant with and without the sparse tile indirection (DDGI_SPARSE_TILES).
            for (const ProgramSpec& s : kGiPrograms) {
                gl::Defines d = render::giShaderDefines(p);
                programs.get(s.vertex, s.fragment, d);
                d["DDGI_SPARSE_TILES"] = "";
                programs.get(s.vertex, s.fragment, d);
            }
            programs.get("fullscreen.vert", "lighting_direct.frag", lighting);
            ++compiled;
            // Each combination's programs deleted before the next: kept, llvmpipe's compiled
            // code of every combination grew the process past 14 GB.
            programs.clear();
        } catch (const Error& e) {
            ADD_FAILURE() << "variant" << (what.empty() ? " defaults" : what) << ": " << e.what();
        }
    }
    std::printf("[ variants ] %s: %d combinations compiled and linked (%zu programs each, GI "
                "programs also with DDGI_SPARSE_TILES)\n",
                GetParam().c_str(), compiled, std::size(kGiPrograms) + 1);
    // Every value of every switch is implemented: every combination must build.
    EXPECT_EQ(compiled, int(combinations.size()));
    EXPECT_GT(compiled, 0);

    // The switch-independent programs.
    gl::Defines counting = render::giShaderDefines(profile::Profile{});
    counting["GI_COUNT_PIXELS"] = "";
    EXPECT_NO_THROW(programs.get("fullscreen.vert", "gi_ddgi_apply.frag", counting));
    EXPECT_NO_THROW(programs.get("gi_volume_box.vert", "gi_ddgi_apply.frag", counting));
    EXPECT_NO_THROW(programs.get("fullscreen.vert", "gi_depth_copy.frag", {}));
    EXPECT_NO_THROW(programs.get("fullscreen.vert", "gi_dynamic_sh_project.frag", {}));
    gl::Defines spheres = render::ddgiConstantDefines();
    EXPECT_NO_THROW(programs.get("debug_probe_sphere.vert", "debug_probe_sphere.frag", spheres));
    spheres["DEBUG_VISIBILITY"] = "";
    EXPECT_NO_THROW(programs.get("debug_probe_sphere.vert", "debug_probe_sphere.frag", spheres));
    // The lighting's gi_only variant (with the default switches' defines).
    gl::Defines giOnly;
    for (const auto& [k, v] : profile::shaderDefines(profile::Profile{}))
        giOnly[k] = v;
    giOnly["GI_ENABLED"] = "";
    giOnly["DEBUG_INDIRECT_ONLY"] = "";
    EXPECT_NO_THROW(programs.get("fullscreen.vert", "lighting_direct.frag", giOnly));
}

PB_INSTANTIATE_HEADLESS_BACKENDS(GiVariantsTest);

} // namespace
} // namespace pb::test
