#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, coverage + ASan + UBSan) into build-fuzz/ and runs each
# for a bounded time on a working corpus (build-fuzz/corpus/<target>/) plus the committed
# seeds (tests/data/fuzz-seeds/<target>/) and probe files baked by build/probebench (when it exists).
# fuzz/README.md explains the targets and the results.
#
#   fuzz/run.sh [SECONDS_PER_TARGET=300] [TARGET...]
#   targets: gltf glb volume_toml profile_toml probe_file
#
# Findings land in build-fuzz/artifacts/<target>/ (crash-*, timeout-*, oom-*, leak-*); replay
# one with `build-fuzz/fuzz/fuzz_<target> FILE`, then keep it as a regression test by copying
# it to tests/data/fuzz-regressions/<target>/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-300}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(gltf glb volume_toml profile_toml probe_file)
out=build-fuzz

CC=clang CXX=clang++ cmake -S . -B "$out" -DCMAKE_BUILD_TYPE=Release -DPB_FUZZ=ON \
    -DPB_BUILD_TESTS=OFF -DPB_BUILD_BENCH=OFF >/dev/null
cmake --build "$out" -j"$(nproc)" --target fuzzers

# Probe-file seeds: tiny bakes in every storage format (skipped without a normal build).
seed_probes() {
    local dir=$out/corpus/probe_file
    [ -x build/probebench ] || return 0
    local toml=$out/probe-seed-volumes.toml
    printf '%s\n' '[[volume]]' 'name = "box"' 'center = [0.0, 1.0, 0.0]' \
        'half_extents = [0.9, 0.9, 0.9]' 'probes = [2, 1, 2]' '' '[[volume]]' \
        'name = "corner"' 'parent = "box"' 'center = [0.4, 0.6, 0.4]' \
        'half_extents = [0.3, 0.3, 0.3]' 'probes = [1, 1, 1]' 'edge_blend = 0.5' >"$toml"
    for f in rgba16f rgba32f bc6h; do
        [ -f "$dir/cornell_$f.pbp" ] ||
            build/probebench bake --scene cornell --volumes "$toml" --rays 16 --bounces 1 \
                --scenario day --scenario night --format "$f" --out "$dir/cornell_$f.pbp" \
                >/dev/null
    done
    # Sparse storage (the storage record, packed tiles): half the probes in open air.
    local yard=$out/probe-seed-yard.toml
    printf '%s\n' '[[volume]]' 'name = "yard"' 'center = [0.0, 8.0, 0.0]' \
        'half_extents = [4.0, 6.0, 4.0]' 'probes = [3, 4, 3]' >"$yard"
    [ -f "$dir/courtyard_sparse_bc6h.pbp" ] ||
        build/probebench bake --scene courtyard --volumes "$yard" --rays 16 --bounces 1 \
            --format bc6h --sparse --out "$dir/courtyard_sparse_bc6h.pbp" >/dev/null
}

for t in "${targets[@]}"; do
    corpus=$out/corpus/$t
    artifacts=$out/artifacts/$t
    mkdir -p "$corpus" "$artifacts" "$out/logs"
    [ "$t" = probe_file ] && seed_probes
    dict=()
    case $t in
    gltf | glb) dict=(-dict=fuzz/dict/gltf.dict) ;;
    *_toml) dict=(-dict=fuzz/dict/toml.dict) ;;
    esac
    echo "==> fuzz_$t for ${seconds}s (corpus $corpus, findings $artifacts/)"
    # -timeout: an input running 10 s is a hang; -rss_limit_mb: 2 GiB is an out-of-memory
    # finding (a few bytes must never make the loader allocate gigabytes).
    set +e
    # New inputs go to the first folder; the committed seeds are read, never written.
    "$out/fuzz/fuzz_$t" "$corpus" "tests/data/fuzz-seeds/$t" "${dict[@]}" -max_total_time="$seconds" \
        -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" \
        >"$out/logs/$t.log" 2>&1
    rc=$?
    set -e
    execs=$(grep 'stat::number_of_executed_units' "$out/logs/$t.log" | awk '{print $2}')
    rate=$(grep 'stat::average_exec_per_sec' "$out/logs/$t.log" | awk '{print $2}')
    cov=$(grep -o 'cov: [0-9]* ft: [0-9]*' "$out/logs/$t.log" | tail -1)
    echo "    exit $rc, ${execs:-?} executions (${rate:-?}/s), $cov," \
        "corpus $(ls "$corpus" | wc -l) files, findings: $(ls "$artifacts" | wc -l)"
done
