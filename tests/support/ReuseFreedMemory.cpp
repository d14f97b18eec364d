// Every test binary allocates as probebench does (core/ReuseFreedMemory.h), before gtest's
// main runs: the tests' bakes and lattice searches then cost what the command's do.
#include "core/ReuseFreedMemory.h"

namespace {
const bool kReusesFreedMemory = (pb::reuseFreedMemory(), true);
} // namespace
