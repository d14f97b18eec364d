#pragma once
// The gate's rows for the weak GPUs' compiler statistics (bench/gate/README.md "Shader
// statistics"): exact per target, profile and pass against the baseline's record of the same
// Mesa; another Mesa's record, or none, is a note; compilers that are not built here are a
// note, except on CI (CI=true) against a baseline that has shader statistics. GL-free.
#include "GateOutcome.h"
#include "GateRecord.h"

#include <string>
#include <vector>

namespace pb::gate {

// `now`: this machine's record; `problems`: shaders::shaderRunProblems' lines ("<target>:
// ..."), each a FAILED row; a target named by one is not compared further. Every counter of
// every pass is exact: a change, an appearing or a vanishing pass fails (exit 3). With no
// baseline record for now.key: a note and a skipped row - except while recording (--update),
// where the rows show what the baseline gains (NEW). The device model's rows (targets
// "model:<device>", PredictionCounters.h) are exact too, except on `otherMachine`
// (GateEnvironment.h), where they pass within kOtherMachineCacheTolerance with a note: their
// memory term is the cache replay's misses, whose last line may differ across CPUs.
void compareShaders(const GateRecord& baseline, const ShaderRecord& now,
                    const std::vector<std::string>& problems, GateOutcome& out,
                    bool otherMachine = false);

// The compilers are not built on this machine (`why`: shaders::findMesaShim's message). A note
// naming scripts/mesa-shim.sh; a FAILED row instead when `onCi` (the environment's CI is
// "true") and the baseline has shader statistics: CI builds the compilers, so their absence
// there is a broken install, not a reason to skip.
void shadersNotBuilt(const GateRecord& baseline, const std::string& why, bool onCi,
                     GateOutcome& out);

// Whether this process runs on CI: the environment variable CI is "true" (GitHub Actions,
// GitLab and most CI services set it so).
bool runningOnCi();

} // namespace pb::gate
