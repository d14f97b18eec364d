#!/bin/sh
# What a sparse probe set's tile indirection costs the GI shader (bench/README.md, "Probe
# placement"): callgrind instruction counts of one frame per profile, rendered the way
# `probebench gate --callgrind` renders it (the gate's rooms suite: view, 384x216, warm-up frames
# uninstrumented, LP_NUM_THREADS=0 so llvmpipe runs on one thread, one dump per pass), once with
# a dense bake and once with a `--sparse` bake of the same volumes (bench/baselines/rooms_gate.toml,
# 128 rays, 2 bounces, rgba16f as the gate bakes). Instruction counts of llvmpipe's code:
# repeatable to a few instructions, not GPU timings.
# Usage, from the repository root after a Release build (needs valgrind):
#   studies/sparse_gi_callgrind.sh [OUT_DIR (build/sparse-callgrind)] [PROFILES (all five)]
# (PB_BIN: another probebench binary than build/probebench.)
# Writes OUT_DIR/{dense,sparse}.pbp, the bake logs and the dumps, and prints a Markdown table.
set -eu
out=${1:-build/sparse-callgrind}
profiles=${2:-reference,console-base,handheld,pc-high,pc-low}
bin=${PB_BIN:-build/probebench}
camera=3,1.6,0,2.02265,1.4143,-0.101475,60 # bench/baselines/rooms.json, suite.camera
volumes=bench/baselines/rooms_gate.toml
mkdir -p "$out"
for kind in dense sparse; do
    "$bin" bake --scene rooms --volumes "$volumes" --rays 128 --bounces 2 --"$kind" \
        --out "$out/$kind.pbp" > "$out/$kind.bake.log"
    rm -rf "${out:?}/$kind"
    mkdir -p "$out/$kind"
    echo "callgrind: $kind ($profiles)" >&2
    LP_NUM_THREADS=0 valgrind --tool=callgrind -q --instr-atstart=no \
        --callgrind-out-file="$out/$kind/cg.out" "$bin" gate-worker --scene rooms \
        --probes "$out/$kind.pbp" --camera "$camera" --width 384 --height 216 --warmup 2 \
        --callgrind-profiles "$profiles"
done
grep -h "probes stored\|sparse-storage candidates" "$out/dense.bake.log" "$out/sparse.bake.log"
# Per dump: "<profile>/<pass> <instructions>"; summed per profile: the GI apply pass and the frame.
sums() {
    for f in "$out/$1"/cg.out.*; do
        awk -F': ' '/^desc: Trigger: Client Request: /{t=$4} /^totals:/{print t, $2}' "$f"
    done | awk '{split($1, p, "/"); frame[p[1]] += $2; if (p[2] == "gi-apply") gi[p[1]] += $2}
                END {for (k in frame) print k, gi[k], frame[k]}' | sort
}
sums dense > "$out/dense.sums"
sums sparse > "$out/sparse.sums"
echo "| profile | gi-apply dense | gi-apply sparse | change | frame dense | frame sparse | change |"
echo "|---|---|---|---|---|---|---|"
join "$out/dense.sums" "$out/sparse.sums" | awk '{
    printf "| %s | %.1f M | %.1f M | %+.1f%% | %.1f M | %.1f M | %+.1f%% |\n", $1, $2 / 1e6,
        $4 / 1e6, ($4 / $2 - 1) * 100, $3 / 1e6, $5 / 1e6, ($5 / $3 - 1) * 100}'
