#!/usr/bin/env bash
# Installs the Debian 12 packages probebench needs (only the missing ones), as root.
# Sourced by run.sh and test.sh; the package list lives here and nowhere else.
PB_PACKAGES=(
    build-essential cmake pkg-config git python3
    libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev
    libglm-dev libglfw3-dev xvfb xauth
    libtinygltf-dev libembree-dev libtomlplusplus-dev nlohmann-json3-dev libstb-dev
    libpng-dev libjpeg62-turbo-dev zlib1g-dev libmeshoptimizer-dev libdraco-dev
    libcli11-dev python3-glad libgtest-dev libbenchmark-dev
    valgrind
    # The HTML report is opened by a real browser in the tests (BenchCli.ReportOpens...).
    chromium
    # A real one-node Slurm cluster for `probebench sweep --engine slurm` and its test
    # (scripts/slurm-local.sh, bench/README.md "Sweeps").
    slurmctld slurmd slurm-client munge
)
# What scripts/mesa-shim.sh needs to build the weak GPUs' compilers from Debian's Mesa source
# (installed by that script, only when it builds).
PB_MESA_BUILD_PACKAGES=(
    meson ninja-build python3-mako bison flex libdrm-dev zlib1g-dev libexpat1-dev pkg-config
    dpkg-dev xz-utils gcc g++
)

# pb_install_deps [PACKAGE...]: the given packages (default: PB_PACKAGES), only the missing ones.
pb_install_deps() {
    local wanted=("$@")
    [ ${#wanted[@]} -gt 0 ] || wanted=("${PB_PACKAGES[@]}")
    local missing=()
    for p in "${wanted[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
            || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    if [ "$(id -u)" -ne 0 ]; then
        echo "probebench: missing Debian packages. Install them with:" >&2
        echo "  sudo apt-get install -y ${missing[*]}" >&2
        return 1
    fi
    echo "==> installing ${#missing[@]} missing packages: ${missing[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q && apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# The weak GPUs' compilers (scripts/mesa-shim.sh) unless PB_MESA_SHIM=0: ./test.sh runs the
# compile tests on them, and a cache makes this a no-op after the first build (5-10 min).
pb_mesa_shim() {
    [ "${PB_MESA_SHIM:-1}" = "0" ] && { echo "==> PB_MESA_SHIM=0: the weak GPUs' compilers are not built; their tests skip"; return 0; }
    scripts/mesa-shim.sh
}

pb_build() {
    local build_dir=${PB_BUILD_DIR:-build}
    echo "==> configuring and building (Release) into $build_dir/"
    cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@" \
        && cmake --build "$build_dir" -j"$(nproc)"
}
