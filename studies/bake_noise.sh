#!/usr/bin/env bash
# The converged bake's figures (studies/findings/bake-noise.md "Bake noise"): per scene, the default bake with
# --seed 1 and --seed 2 (wall time and the summary's noise line), then bench_bake_noise on the
# pair. Extra bake options (e.g. --noise-target 0 --emitter-samples 0 for the old bake) pass
# through.  Usage: studies/bake_noise.sh OUT_DIR SCENE... [-- BAKE_OPTIONS...]
set -euo pipefail
out=$1; shift
scenes=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do scenes+=("$1"); shift; done
[ "${1:-}" = "--" ] && shift
mkdir -p "$out"
for s in "${scenes[@]}"; do
    name=$(basename "$s"); name=${name%%.*}
    for seed in 1 2; do
        /usr/bin/time -f "$name seed $seed: %e s wall" build/probebench bake --scene "$s" \
            --seed "$seed" --force --out "$out/$name-$seed.probes" "$@" | grep -E '^noise|^time'
    done
    build/studies/bench_bake_noise "$s" "$out/$name-1.probes" "$out/$name-2.probes"
done
