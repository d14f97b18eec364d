#!/bin/sh
# The GI apply pass against its texture-fetch floor in instructions (issue 17 P1; studies/README.md
# "GI pass over its fetch floor"): callgrind instruction counts of llvmpipe rendering one frame
# per profile the way `probebench gate --callgrind` renders it (gate-worker: warm-up frames
# uninstrumented, LP_NUM_THREADS=0 so llvmpipe runs on one thread, glFinish and one dump per
# pass), followed by the bench's fetch floor (bench/runner/FetchFloorPass, its own dump). An
# uninstrumented counting frame before it gives the GI pass's evaluations (GiPassStats).
#   per evaluation: gi-apply instructions / evaluations
#   per texel:      gi-fetch-floor instructions / GI target texels (the floor does one lookup's
#                   fetches at every texel)
#   ratio:          the two divided: the pass's cost per lookup over the floor's per lookup.
# Inputs: the gate suite's committed probe data (bench/baselines/rooms.probes.gz, volumes
# rooms_gate.toml) and its camera (the bench's worst-case view of rooms), so anyone gets the same
# counts with the same Mesa/LLVM/compiler; instruction counts are load-independent, not GPU
# timings. Usage, from the repository root after a Release build (needs valgrind):
#   studies/gi_floor_callgrind.sh [OUT_DIR (build/floor-callgrind)] [PROFILES (reference)] [WxH (512x288)]
# (PB_BIN: another probebench binary than build/probebench.) Prints a Markdown table.
set -eu
out=${1:-build/floor-callgrind}
profiles=${2:-reference}
size=${3:-512x288}
bin=${PB_BIN:-build/probebench}
camera=3,1.6,0,2.02265,1.4143,-0.101475,60 # bench/baselines/rooms.json, suite.camera
mkdir -p "$out"
rm -f "$out"/cg.out.*
gzip -dc bench/baselines/rooms.probes.gz > "$out/rooms.pbp"
echo "callgrind: $profiles at $size (minutes)" >&2
LP_NUM_THREADS=0 valgrind --tool=callgrind -q --instr-atstart=no \
    --callgrind-out-file="$out/cg.out" "$bin" gate-worker --scene rooms \
    --probes "$out/rooms.pbp" --camera "$camera" --width "${size%x*}" --height "${size#*x}" \
    --warmup 2 --callgrind-profiles "$profiles" --callgrind-floor > "$out/worker.log"
# "<profile> <gi-apply instructions> <floor instructions>"
for f in "$out"/cg.out.*; do
    awk -F': ' '/^desc: Trigger: Client Request: /{t=$4} /^totals:/{print t, $2}' "$f"
done | awk '{split($1, p, "/"); if (p[2] == "gi-apply") gi[p[1]] += $2;
            if (p[2] == "gi-fetch-floor") fl[p[1]] += $2}
            END {for (k in gi) print k, gi[k], fl[k]}' | sort > "$out/sums"
grep '^gi-evaluations ' "$out/worker.log" | awk '{print $2, $3, $4}' | sort > "$out/evaluations"
echo "| profile | evaluations | per texel | gi-apply instr. | per evaluation | floor instr. | per texel | ratio per evaluation | ratio per texel |"
echo "|---|---|---|---|---|---|---|---|---|"
join "$out/sums" "$out/evaluations" | awk '{
    pe = $2 / $4; pt = $3 / $5;
    printf "| %s | %d | %.3f | %.1f M | %.0f | %.1f M | %.0f | %.2f | %.2f |\n", $1, $4, $4 / $5,
        $2 / 1e6, pe, $3 / 1e6, pt, pe / pt, ($2 / $5) / pt}'
