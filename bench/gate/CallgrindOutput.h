#pragma once
// Reading what `valgrind --tool=callgrind` wrote for the gate's instruction counts (GL-free):
// the worker dumps the counts at every frame-section boundary with CALLGRIND_DUMP_STATS_AT
// ("<profile>/<section>"), so each dump file holds the instructions of one section of one
// profile's frame (bench/gate_gl/CallgrindFrame.h).
#include "GateRecord.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pb::gate {

struct CallgrindDump {
    std::string trigger; // "Client Request: <name>" -> <name>; others (termination) -> ""
    std::uint64_t instructions = 0;
};

// One dump file's trigger and "totals:" (events: Ir). Throws pb::Error naming the file when
// it cannot be read or has no totals.
CallgrindDump readCallgrindDump(const std::string& path);

// Dumps named "<profile>/<section>" folded per profile, sections in first-seen order with
// repeats summed, plus "frame" = their sum. Other dumps are ignored.
std::vector<std::pair<std::string, Counters>>
callgrindProfiles(const std::vector<CallgrindDump>& dumps);

// The toolchain key from the GL strings ("OpenGL ES 3.2 Mesa 22.3.6", "llvmpipe (LLVM 15.0.6,
// 256 bits)"), the compiler's __VERSION__ and `valgrind --version`. Parts not found read
// "unknown".
CallgrindKey callgrindKey(const std::string& glVersion, const std::string& glRenderer,
                          const std::string& compiler, const std::string& valgrindVersion);

} // namespace pb::gate
