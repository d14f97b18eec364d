// probebench gate-worker: the process `probebench gate` starts for its timing rounds (one per
// binary with --against) and, under valgrind, for its instruction counts. Internal: hidden
// from --help; the protocol is in bench/gate_gl/GateWorker.h.
#include "CommandRegistry.h"
#include "PlatformOptions.h"
#include "ProfileOptions.h"
#include "SceneOptions.h"
#include "bench/gate_gl/CallgrindFrame.h"
#include "bench/gate_gl/GateWorker.h"
#include "bench/runner/SectionTimer.h"
#include "core/Error.h"
#include "gl/Capabilities.h"
#include "gl/DriverQuirks.h"
#include "probes/store/ProbeFile.h"

#include <iostream>

namespace pb::app {
namespace {

struct WorkerArgs {
    SceneArgs scene;
    platform::PlatformOptions platform;
    std::string probes, camera, timing = "cpu-time";
    int width = 384, height = 216, warmup = 2;
    std::vector<std::string> callgrindProfiles;
    bool callgrindFloor = false;
};

int serve(const WorkerArgs& a) {
    gate::WorkerOptions o;
    const scene::Scene s = loadSceneWithOverrides(a.scene);
    const probes::ProbeSet set = probes::readProbeFile(a.probes);
    o.inputs.scene = &s;
    o.inputs.probes = &set;
    o.inputs.view = chooseView(s, "", a.camera);
    o.inputs.settings = render::defaultFrameSettings(s);
    o.inputs.width = a.width;
    o.inputs.height = a.height;
    o.inputs.warmup = a.warmup;
    o.search = profileSearch();
    platform::PlatformOptions po = a.platform;
    po.debugContext = false; // the timing must not pay for KHR_debug's checks
    auto platform = platform::createPlatform(po);
    if (!a.callgrindProfiles.empty()) {
        std::vector<profile::PlatformProfile> profiles;
        for (const std::string& n : a.callgrindProfiles)
            profiles.push_back(profile::loadProfile(n, o.search));
        gate::renderCallgrindFrames(o.inputs, profiles, a.callgrindFloor);
        return 0;
    }
    const gl::GlCaps caps = gl::queryCaps();
    o.timing = bench::chooseTiming(a.timing, caps, gl::detectDriverQuirks());
    o.es = caps.es;
    return gate::serveGateWorker(o, std::cin, std::cout);
}

// Protocol mode reports a failed start on stdout too, so the gate names the real problem.
int runGateWorker(const WorkerArgs& a) {
    if (!a.callgrindProfiles.empty()) return serve(a);
    try {
        return serve(a);
    } catch (const std::exception& e) {
        std::cout << "error " << e.what() << std::endl;
        return 1;
    }
}

const RegisterCommand registerGateWorker{
    {"gate-worker", "Internal: the timing and callgrind worker of `probebench gate`", 1000,
     [](CLI::App& cmd) {
         cmd.group(""); // hidden from `probebench --help`
         auto a = std::make_shared<WorkerArgs>();
         addSceneOptions(cmd, a->scene);
         addPlatformOptions(cmd, a->platform);
         cmd.add_option("--probes", a->probes, "Probe file")->required();
         cmd.add_option("--camera", a->camera, "Camera px,py,pz,tx,ty,tz[,fovdeg]")->required();
         cmd.add_option("--width", a->width, "Frame width")->capture_default_str();
         cmd.add_option("--height", a->height, "Frame height")->capture_default_str();
         cmd.add_option("--timing", a->timing, "Timing method (as probebench bench --timing)")
             ->check(CLI::IsMember(bench::timingRequestNames()))
             ->capture_default_str();
         cmd.add_option("--warmup", a->warmup, "Warm-up frames per profile")->capture_default_str();
         cmd.add_option("--callgrind-profiles", a->callgrindProfiles,
                        "Render one instrumented frame of each (under valgrind only)")
             ->delimiter(',');
         cmd.add_flag("--callgrind-floor", a->callgrindFloor,
                      "With --callgrind-profiles: also dump the GI fetch floor and print the GI "
                      "pass's evaluations (studies/gi_floor_callgrind.sh)");
         return [a] { return runGateWorker(*a); };
     }}};

} // namespace
} // namespace pb::app
