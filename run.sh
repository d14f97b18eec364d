#!/usr/bin/env bash
# Installs what is missing, builds, bakes and renders the Cornell box with probe GI and without
# (out/cornell_gi.png, out/cornell_direct.png), then runs the default benchmark:
# the built-in `rooms` scene (a volume per room nested in one over the house), every profile,
# with ablation, in the worst-case view; writes out/report.html (self-contained) and
# out/bench.json, prints the Markdown summary. A few minutes on 2 cores (bench/README.md).
set -euo pipefail
cd "$(dirname "$0")"
source scripts/deps.sh
pb_install_deps
pb_build
# The first picture: the Cornell box with probe GI and its direct-only twin (probes cached in
# out/; scripts/first-run.sh says how).
scripts/first-run.sh build/probebench out
echo "==> first run: $(pwd)/out/cornell_gi.png (probe GI) beside out/cornell_direct.png (direct light only)"
# 512x288 for every profile keeps llvmpipe within minutes and puts every profile in one set of
# interleaved rounds; 6 rounds is the fewest that give a 95% interval for the deltas; each round
# times 3 steady frames per variant after an untimed switch frame. --cache-dir keeps the baked
# probes in out/.
# Where scripts/mesa-shim.sh has built the weak GPUs' compilers (./test.sh does), the report
# also shows every profile's programs as the Adreno 630, Mali-G52 and Mali-G57 compilers see them,
# and the device model's prediction of every profile on its own target device ([budget] model:
# the Switch, the Xbox One, the GTX 1080), its budget judged there (bench/README.md "Frame time
# on the target devices").
targets=()
if scripts/mesa-shim.sh --print > /dev/null 2>&1; then
    targets=(--targets adreno-630,mali-g52,mali-g57 --predict own)
else
    echo "==> the weak GPUs' compilers are not built: scripts/mesa-shim.sh builds them (about 10 min) for the report's compiler and device-model sections"
fi
./build/probebench bench --scene rooms --volumes bench/volumes/rooms_nested.toml --ablate \
    --width 512 --height 288 --rounds 6 --frames 3 --warmup 2 --cache-dir out/cache \
    --json out/bench.json --html out/report.html "${targets[@]}"
echo "==> report: $(pwd)/out/report.html (open in a browser; JSON: out/bench.json)"
