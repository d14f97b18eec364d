#include "CallgrindFrame.h"

#include "WorkerProcess.h"
#include "bench/gate/CallgrindOutput.h"
#include "bench/runner/FetchFloorPass.h"
#include "core/Error.h"
#include "passes/GiApplyPass.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include <glad/gl.h>

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define PB_HAVE_CALLGRIND 1
#else
#define PB_HAVE_CALLGRIND 0
#endif

namespace pb::gate {

namespace fs = std::filesystem;

namespace {

#if PB_HAVE_CALLGRIND
// Dumps the instructions since the last dump under the innermost open section's name.
class CallgrindTimer : public render::FrameTimer {
public:
    explicit CallgrindTimer(std::string profile) : profile_(std::move(profile)) {}
    void begin(const char* section) override {
        dump();
        open_.push_back(section);
    }
    void end(const char*) override {
        dump();
        if (!open_.empty()) open_.pop_back();
    }
    void dump() {
        glFinish(); // llvmpipe finishes the queued work of the section on this thread
        const std::string name = profile_ + "/" + (open_.empty() ? "(outside)" : open_.back());
        CALLGRIND_DUMP_STATS_AT(name.c_str());
    }

private:
    std::string profile_;
    std::vector<std::string> open_;
};
#endif

std::string compilerVersion() {
#if defined(__clang__)
    return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
    return std::string("GCC ") + __VERSION__;
#else
    return "unknown";
#endif
}

} // namespace

bool callgrindSupported() {
    return PB_HAVE_CALLGRIND;
}

void renderCallgrindFrames(const GateInputs& in,
                           const std::vector<profile::PlatformProfile>& profiles, bool floor) {
#if PB_HAVE_CALLGRIND
    if (!RUNNING_ON_VALGRIND)
        throw Error("--callgrind-profiles: run under valgrind --tool=callgrind (the gate does)");
    for (const profile::PlatformProfile& p : profiles) {
        GateRenderer r(in, p); // warm-up frames, uninstrumented
        std::unique_ptr<bench::FetchFloorPass> floorPass;
        if (floor) {
            render::GiApplyPass* gi = r.renderer().giApplyPass();
            if (!gi) throw Error("--callgrind-floor: profile '" + p.name + "' has no GI pass");
            // The counted frame comes right after a camera cut, as the gate's (GateMeasure.cpp).
            r.renderer().resetGiHistory();
            gi->setCountPixels(true);
            r.frame();
            gi->setCountPixels(false);
            const render::GiPassStats& s = gi->stats();
            std::cout << "gi-evaluations " << p.name << " " << s.totalEvaluations() << " "
                      << std::int64_t(s.width) * s.height << std::endl;
            r.renderer().resetGiHistory();
            r.frame();
            floorPass = std::make_unique<bench::FetchFloorPass>(p.switches);
            floorPass->execute(r.renderer(), r.view()); // compiles its shader, uninstrumented
            glFinish(); // llvmpipe rasterises queued draws at the next flush: not in a dump
        }
        CALLGRIND_START_INSTRUMENTATION;
        CALLGRIND_ZERO_STATS;
        CallgrindTimer timer(p.name);
        r.frame(&timer);
        if (floorPass) {
            timer.begin("gi-fetch-floor");
            floorPass->execute(r.renderer(), r.view());
            timer.end("gi-fetch-floor");
        }
        timer.dump();
        CALLGRIND_STOP_INSTRUMENTATION;
    }
#else
    (void)in;
    (void)profiles;
    (void)floor;
    throw Error("--callgrind: this build has no valgrind/callgrind.h (Debian: valgrind)");
#endif
}

CallgrindKey currentCallgrindKey(const std::string& glVersion, const std::string& glRenderer) {
    std::string valgrind;
    try {
        WorkerProcess v({"valgrind", "--version"}, {}, "valgrind");
        valgrind = v.readLine();
    } catch (const Error&) {
        throw Error("--callgrind: valgrind not found (Debian: apt-get install valgrind)");
    }
    return callgrindKey(glVersion, glRenderer, compilerVersion(), valgrind);
}

CallgrindRecord runCallgrind(const std::vector<std::string>& workerArgv,
                             const std::string& glVersion, const std::string& glRenderer,
                             const std::string& outDir) {
    if (!callgrindSupported())
        throw Error("--callgrind: this build has no valgrind/callgrind.h (Debian: valgrind)");
    CallgrindRecord rec;
    rec.key = currentCallgrindKey(glVersion, glRenderer);
    std::error_code ec;
    fs::remove_all(outDir, ec);
    fs::create_directories(outDir, ec);
    if (ec) throw fileError(outDir, "cannot create the callgrind output folder");
    std::vector<std::string> argv{"valgrind", "--tool=callgrind", "-q", "--instr-atstart=no",
                                  "--callgrind-out-file=" + (fs::path(outDir) / "cg.out").string()};
    argv.insert(argv.end(), workerArgv.begin(), workerArgv.end());
    const int status = runProcess(argv, {"LP_NUM_THREADS=0"});
    if (status != 0)
        throw Error("--callgrind: the worker under valgrind failed (exit " +
                    std::to_string(status) + ")");
    std::vector<std::string> files;
    for (const auto& e : fs::directory_iterator(outDir))
        if (e.path().filename().string().rfind("cg.out.", 0) == 0) files.push_back(e.path());
    // cg.out.N: dump N, in the order the frame made them.
    std::sort(files.begin(), files.end(), [](const std::string& a, const std::string& b) {
        return std::stoi(a.substr(a.rfind('.') + 1)) < std::stoi(b.substr(b.rfind('.') + 1));
    });
    std::vector<CallgrindDump> dumps;
    for (const std::string& f : files)
        dumps.push_back(readCallgrindDump(f));
    rec.profiles = callgrindProfiles(dumps);
    if (rec.profiles.empty()) throw Error("--callgrind: valgrind wrote no per-pass dumps");
    return rec;
}

} // namespace pb::gate

#undef PB_HAVE_CALLGRIND // this file's own (a unity build would carry it on)
