#pragma once
// Instruction counts of one frame per profile under valgrind's callgrind (bench/gate/README.md
// "Instruction counts"). The gate starts `valgrind --tool=callgrind --instr-atstart=no
// probebench gate-worker ... --callgrind-profiles a,b` with LP_NUM_THREADS=0 (llvmpipe
// rasterises on the calling thread: one deterministic instruction stream). The worker warms
// every profile up uninstrumented (shader compilation, the first frames), then turns
// instrumentation on with callgrind's client requests (valgrind/callgrind.h), renders one
// frame whose sections each end with glFinish and CALLGRIND_DUMP_STATS_AT("<profile>/<pass>"),
// and turns it off again: each dump holds exactly one pass of one profile.
// With `floor` (studies/gi_floor_callgrind.sh, not the gate) the instrumented frame is followed by
// the GI pass's texture-fetch floor (bench/runner/FetchFloorPass) dumped as
// "<profile>/gi-fetch-floor", and before it an uninstrumented frame counting the GI pass's
// evaluations (GiPassStats) prints one line per profile on stdout:
//   "gi-evaluations <profile> <total evaluations> <GI target texels>"
// so instructions per evaluation (gi-apply) and per texel (floor) can be compared.
#include "GateMeasure.h"
#include "bench/gate/GateRecord.h"
#include "profile/PlatformProfile.h"

#include <functional>
#include <string>
#include <vector>

namespace pb::gate {

// Whether this build has callgrind's client requests (Debian: the valgrind package).
bool callgrindSupported();
// Worker side; throws pb::Error when not running under valgrind or built without support.
void renderCallgrindFrames(const GateInputs& in,
                           const std::vector<profile::PlatformProfile>& profiles,
                           bool floor = false);

// Gate side: runs `workerArgv` (ending in --callgrind-profiles) under callgrind in `outDir`
// and reads the dumps. The key: this context's GL strings, the compiler of this build and
// `valgrind --version`. Throws pb::Error (valgrind missing, the run failed, no dumps).
CallgrindRecord runCallgrind(const std::vector<std::string>& workerArgv,
                             const std::string& glVersion, const std::string& glRenderer,
                             const std::string& outDir);
// The key of this machine without running anything but `valgrind --version`.
CallgrindKey currentCallgrindKey(const std::string& glVersion, const std::string& glRenderer);

} // namespace pb::gate
