#!/usr/bin/env bash
# The unit tests under AddressSanitizer + UndefinedBehaviorSanitizer: a second build tree,
# build-asan/, configured with -DPB_SANITIZE=ON (UB aborts the test; leaks fail it too).
# CI runs it after ./test.sh (.ci/run). Extra arguments go to ctest.
#   scripts/test-sanitized.sh                 # build + every unit test
#   scripts/test-sanitized.sh -R GltfHostile  # a subset
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/deps.sh
pb_install_deps
# -O1: 4 min 44 s of CPU for this whole script against 12 min 26 s for the -O3 build alone
# (2-core VM, README.md "Robustness"), tests still fast;
# no NDEBUG, so asserts stay on.
echo "==> configuring and building the unit tests with ASan + UBSan into build-asan/"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE=-O1 \
    -DCMAKE_C_FLAGS_RELEASE=-O1 -DPB_SANITIZE=ON -DPB_BUILD_BENCH=OFF
cmake --build build-asan -j"$(nproc)" --target unit_tests
cd build-asan
# Tests that run under ASan 8-10x longer than in Release (45-165 s each on the 2-core VM, 40% of
# this stage's test time) and whose code the sanitizers see in lighter tests: they place with the
# lattice search or bake converged probes only on the way to what they check (nesting, coverage,
# memory, planes, seed agreement). The search itself stays in, as
# AutoPlacement.LatticeSearchOnlyShiftsWithinTheBudgetAndIsDeterministic, and so do the noise
# rounds (every bake at the default noise target). ./test.sh runs all of them in Release.
heavy=(
    AutoPlacement.EveryChildLiesInsideItsParent
    AutoPlacement.DefaultStaysWithinTheDefaultUniformMemory
    BenchView.WorstCaseIsFullyCoveredWithTheBenchsAutoVolumes
    LatticeAlignment.AutoKeepsTheBoundaryWallsOffItsProbePlanes
    NoiseTarget.TwoCornellBakesWithDifferentSeedsAgreeWithinThreePercent
)
skip="^($(IFS='|'; echo "${heavy[*]}"))\$"
UBSAN_OPTIONS=print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1 \
    ctest --output-on-failure -j"$(nproc)" -L unit_tests -E "$skip" "$@"
