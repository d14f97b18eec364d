// Every combination of the shader-visible profile switches (the SwitchTable rows with a
// #define) compiles and links on egl and osmesa: the apply pass, the point evaluator and the
// lighting variant. Generated from the table, so a new switch is covered without editing
// this file. Values the pass does not implement yet are counted and reported, not compiled.
#include "gl/GlTestFixture.h"

#include "core/Error.h"
#include "gl/ProgramCache.h"
#include "passes/GiApplyPass.h"
#include "profile/SwitchTable.h"

#include <cstdio>

namespace pb::test {
namespace {

std::vector<profile::Profile> allShaderCombinations() {
    std::vector<profile::Profile> out(1);
    for (const profile::SwitchInfo& s : profile::switchTable()) {
        if (s.defineStyle == profile::DefineStyle::HostOnly ||
            s.kind != profile::SwitchKind::Choice)
            continue;
        std::vector<profile::Profile> next;
        for (const profile::Profile& p : out)
            for (const std::string& v : s.choices) {
                next.push_back(p);
                next.back().set(s.key, v);
            }
        out = std::move(next);
    }
    return out;
}

class GiVariantsTest : public GlBackendTest {};

TEST_P(GiVariantsTest, EveryCombinationCompilesAndLinks) {
    int compiled = 0, notImplemented = 0;
    gl::ProgramCache programs;
    for (const profile::Profile& p : allShaderCombinations()) {
        try {
            render::checkGiProfileSupported(p);
        } catch (const Error&) {
            ++notImplemented;
            continue;
        }
        gl::Defines lighting;
        for (const auto& [k, v] : profile::shaderDefines(p))
            lighting[k] = v;
        lighting["GI_ENABLED"] = "";
        std::string what;
        for (const auto& c : p.changedSwitches())
            what += " " + c;
        try {
            programs.get("fullscreen.vert", "gi_ddgi_apply.frag", render::giShaderDefines(p));
            programs.get("fullscreen.vert", "gi_ddgi_points.frag", render::giShaderDefines(p));
            programs.get("fullscreen.vert", "lighting_direct.frag", lighting);
            ++compiled;
        } catch (const Error& e) {
            ADD_FAILURE() << "variant" << (what.empty() ? " defaults" : what) << ": " << e.what();
        }
    }
    std::printf("[ variants ] %s: %d combinations compiled and linked (3 programs each), %d use "
                "values not implemented yet\n",
                GetParam().c_str(), compiled, notImplemented);
    EXPECT_GT(compiled, 0);
}

PB_INSTANTIATE_HEADLESS_BACKENDS(GiVariantsTest);

} // namespace
} // namespace pb::test
