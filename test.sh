#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test through ctest.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/deps.sh
pb_install_deps
pb_mesa_shim # the weak GPUs' compilers for their tests (PB_MESA_SHIM=0 skips; cached)
pb_build
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
