#!/usr/bin/env bash
# Installs what is missing, builds, renders the default scene, then runs the default benchmark:
# the built-in `rooms` scene (a volume per room nested in one over the house), every profile,
# with ablation, in the worst-case view; writes out/report.html (self-contained) and
# out/bench.json, prints the Markdown summary. A few minutes on 2 cores (bench/README.md).
set -euo pipefail
cd "$(dirname "$0")"
source scripts/deps.sh
pb_install_deps
pb_build
mkdir -p out
./build/probebench render --scene cornell --out out/cornell.png --out-hdr out/cornell.pfm
echo "==> results: $(pwd)/out/cornell.png (8-bit sRGB) and out/cornell.pfm (linear HDR)"
# 512x288 for every profile keeps llvmpipe well under 5 minutes; 6 interleaved rounds is the
# fewest that give a 95% interval for the deltas. --cache-dir keeps the baked probes in out/.
./build/probebench bench --scene rooms --volumes bench/volumes/rooms_nested.toml --ablate \
    --width 512 --height 288 --rounds 6 --frames 1 --warmup 2 --cache-dir out/cache \
    --json out/bench.json --html out/report.html
echo "==> report: $(pwd)/out/report.html (open in a browser; JSON: out/bench.json)"
