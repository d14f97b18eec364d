#!/usr/bin/env bash
# Runs a command on one weak GPU's compiler: probebench shaders --exec TARGET -- COMMAND...
# Exit 77 (ctest: skipped) when scripts/mesa-shim.sh has not built the compilers; under CI=true
# that is a failure, since CI builds them (.ci/run).
# Usage: on_shader_target.sh PROBEBENCH TARGET COMMAND [ARGS...]
set -euo pipefail
probebench=$1
target=$2
shift 2
here=$(cd "$(dirname "$0")/../.." && pwd)
if ! "$here/scripts/mesa-shim.sh" --print > /dev/null 2>&1; then
    if [ "${CI:-}" = "true" ]; then
        echo "the weak GPUs' compilers are not built under CI (scripts/mesa-shim.sh)" >&2
        exit 1
    fi
    echo "skipped: the weak GPUs' compilers are not built (scripts/mesa-shim.sh)"
    exit 77
fi
exec "$probebench" shaders --exec "$target" -- "$@"
