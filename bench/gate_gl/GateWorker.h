#pragma once
// The timing worker behind `probebench gate --against` (apps/cmd_gate_worker.cpp runs it):
// one process per binary, each rendering only when asked, so baseline and candidate rounds
// interleave in time while neither process's state (heap, JIT code, caches) touches the
// other's. Protocol, one line each way (WorkerProcess.h):
//   worker: "ready probebench-gate-worker/2"
//   gate:   "load NAME"      -> "ok"                 (builds the profile, warm-up frames)
//   gate:   "round NAME K"   -> "times FRAME_MS GI_MS" (K frames: the medians)
//   gate:   "quit"
//   any failure -> "error <one line>" and exit 1.
// The same command, under valgrind, renders the callgrind frames (CallgrindFrame.h).
#include "GateMeasure.h"
#include "GateTiming.h"
#include "bench/runner/SectionTimer.h"
#include "profile/ProfileLoader.h"

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace pb::gate {

// The protocol's version is in the hello. 2: GI_MS sums bench/report/GiSections.h's passes
// (upsample included); 1 summed the gi-* sections only, so its GI times do not compare.
inline constexpr const char* kWorkerHello = "ready probebench-gate-worker/2";

// Throws a one-line pb::Error naming `label` unless `hello` is this gate's kWorkerHello: a
// worker of another protocol version says which, anything else is not a gate worker.
void checkWorkerHello(const std::string& hello, const std::string& label);

struct WorkerOptions {
    GateInputs inputs;
    bench::TimingChoice timing;
    bool es = true;
    profile::ProfileSearch search;
};

// Serves the protocol on in/out until "quit" (0) or a failure (1, after "error ...").
int serveGateWorker(const WorkerOptions& o, std::istream& in, std::ostream& out);

class WorkerProcess;
// The against timing of one profile: `baseline` and `candidate` workers (both ready); two
// quantities per round, each decided per TimingDecision.h: "frame" (the whole frame, what a
// user sees) and "gi" (the GI passes of bench/report/GiSections.h: where this testbed's
// changes land, and a smaller denominator for them).
SequentialTiming timeAgainst(WorkerProcess& baseline, WorkerProcess& candidate,
                             const std::string& profile, const TimingSettings& s, int budget,
                             double timeBudgetSeconds,
                             const std::function<void(const std::string&)>& progress);

} // namespace pb::gate
