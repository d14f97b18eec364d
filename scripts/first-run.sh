#!/usr/bin/env bash
# The first picture of ./run.sh: the built-in Cornell box - closed, lit only by its ceiling
# panel - baked once (cached: a re-run prints "up to date") and rendered twice from its classic
# `front` view: with probe GI, and with direct light only. Everything the walls show in the
# first and not in the second is what the probes add.
# Usage: scripts/first-run.sh [PROBEBENCH] [OUT_DIR]   (defaults: build/probebench, out)
set -euo pipefail
bin=${1:-build/probebench}
out=${2:-out}
mkdir -p "$out"
"$bin" bake --scene cornell --out "$out/cornell.probes"
"$bin" render --scene cornell --view front --probes "$out/cornell.probes" \
    --out "$out/cornell_gi.png" --out-hdr "$out/cornell_gi.pfm"
"$bin" render --scene cornell --view front \
    --out "$out/cornell_direct.png" --out-hdr "$out/cornell_direct.pfm"
