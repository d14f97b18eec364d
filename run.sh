#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job on the built-in default scene.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/deps.sh
pb_install_deps
pb_build
mkdir -p out
./build/probebench render --scene cornell --out out/cornell.png --out-hdr out/cornell.pfm
echo "==> results: $(pwd)/out/cornell.png (8-bit sRGB) and out/cornell.pfm (linear HDR)"
