#pragma once
// LLVMFuzzerTestOneInput for one runner of FuzzInputs.h: a broken contract aborts, which
// libFuzzer records as a crash (with the input saved as crash-<sha1>).
#include "fuzz/FuzzInputs.h"

#include <cstdio>
#include <cstdlib>

#define PB_FUZZ_TARGET(run)                                                                        \
    extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {            \
        try {                                                                                      \
            (void)(run);                                                                           \
        } catch (const pb::fuzz::ContractViolation& e) {                                           \
            std::fprintf(stderr, "probebench fuzz: contract violation: %s\n", e.what());           \
            std::abort();                                                                          \
        }                                                                                          \
        return 0;                                                                                  \
    }
