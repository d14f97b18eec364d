#!/usr/bin/env bash
# Line coverage of the readers reached by the working corpus of fuzz/run.sh: builds the
# targets with llvm-cov instrumentation into build-fuzz-cov/, replays build-fuzz/corpus/<t>
# and tests/data/fuzz-seeds/<t>
# (no fuzzing, -runs=0), and prints llvm-cov's per-file table for the project's own files.
#   fuzz/coverage.sh [TARGET...]      targets: gltf glb volume_toml probe_file
set -euo pipefail
cd "$(dirname "$0")/.."
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(gltf glb volume_toml probe_file)
out=build-fuzz-cov
CC=clang CXX=clang++ cmake -S . -B "$out" -DCMAKE_BUILD_TYPE=Release -DPB_FUZZ=ON \
    -DPB_FUZZ_COVERAGE=ON -DPB_BUILD_TESTS=OFF -DPB_BUILD_BENCH=OFF >/dev/null
cmake --build "$out" -j"$(nproc)" --target fuzzers
mkdir -p "$out/profiles"
objects=()
for t in "${targets[@]}"; do
    LLVM_PROFILE_FILE="$out/profiles/$t.profraw" "$out/fuzz/fuzz_$t" -runs=0 \
        "build-fuzz/corpus/$t" "tests/data/fuzz-seeds/$t" >"$out/profiles/$t.log" 2>&1
    objects+=(-object "$out/fuzz/fuzz_$t")
done
llvm-profdata merge -sparse "$out"/profiles/*.profraw -o "$out/profiles/merged.profdata"
llvm-cov report "${objects[@]:1}" -instr-profile="$out/profiles/merged.profdata" \
    "$PWD/renderer/scene" "$PWD/renderer/probes/ProbeFile.cpp" \
    "$PWD/renderer/probes/VolumeFile.cpp" "$PWD/renderer/probes/ProbeVolume.cpp" \
    "$PWD/renderer/probes/ProbeSampler.cpp" "$PWD/renderer/probes/StorageFormat.cpp" \
    "$PWD/renderer/core" "$PWD/fuzz"
