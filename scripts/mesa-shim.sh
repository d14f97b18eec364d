#!/usr/bin/env bash
# Builds the weak GPUs' own shader compilers - Mesa's freedreno (Adreno), panfrost (Mali),
# v3d (Raspberry Pi 4) and nouveau (Tegra X1) drivers with their drm-shims - from Debian 12's
# own Mesa source package, into a cache folder keyed by the Mesa version and these options.
# `probebench shaders` runs probebench on them (bench/shaders/README.md).
#
#   scripts/mesa-shim.sh            # build into the cache, or say it is there (a no-op)
#   scripts/mesa-shim.sh --print    # print the cache folder, build nothing (exit 1: not built)
#
# The cache: $PB_MESA_SHIM_ROOT (default /var/cache/probebench/mesa-shim)/<version>-<key>/,
# complete only when it holds the file `complete`: the install goes to a temporary folder
# that is renamed into place last, so an interrupted build never leaves a half-installed cache.
# Mesa's code never enters the repository: the source comes from apt (a deb-src entry for the
# archive the machine already uses is added under /etc/apt/sources.list.d/), nothing else is
# downloaded. 5-10 minutes on 2 cores, 1 GiB of temporary disk, 21 MB in the cache.
set -euo pipefail

# Choose the set once: each gallium driver adds a global define, so adding one later rebuilds
# everything. vc4's 22.3.6 shim lacks ioctls and lima/etnaviv are GLES 2 parts; nouveau is
# here for the Switch's Tegra X1 (its shim is built only with the gallium driver).
PB_MESA_DRIVERS=freedreno,panfrost,v3d,nouveau
source "$(dirname "$0")/deps.sh" # PB_MESA_BUILD_PACKAGES, pb_install_deps
# What the build needs of meson. Changing this list changes the cache key.
PB_MESA_OPTIONS=(-Dbuildtype=plain -Doptimization=1 -Db_ndebug=true -Dplatforms=
    -Degl=enabled -Dgbm=disabled -Dglx=disabled -Dglvnd=false -Dgles1=disabled
    -Dgles2=enabled "-Dgallium-drivers=$PB_MESA_DRIVERS" -Dvulkan-drivers= -Dllvm=disabled
    -Dvalgrind=disabled -Dlibunwind=disabled -Dlmsensors=disabled -Dgallium-vdpau=disabled
    -Dgallium-va=disabled -Dgallium-xa=disabled -Dgallium-omx=disabled -Dgallium-nine=false
    -Dgallium-opencl=disabled -Dbuild-tests=false -Dtools=drm-shim -Dzstd=disabled)

die() { echo "mesa-shim: $*" >&2; exit 1; }

# The installed Mesa's version: the compilers match the llvmpipe the tests already use.
mesa_version() {
    dpkg-query -W -f='${Version}' libgl1-mesa-dri 2>/dev/null \
        || die "libgl1-mesa-dri is not installed (run scripts/deps.sh's pb_install_deps first)"
}

cache_dir() {
    local root=${PB_MESA_SHIM_ROOT:-/var/cache/probebench/mesa-shim}
    local key
    key=$(printf '%s\n' "${PB_MESA_OPTIONS[@]}" | sha256sum | cut -c1-10)
    echo "$root/$(mesa_version | tr ':+~' '___')-$key"
}

install_build_packages() {
    pb_install_deps "${PB_MESA_BUILD_PACKAGES[@]}" \
        || die "the build packages are missing (the line above installs them)"
}

# A deb-src entry for every archive the deb entries name, so `apt-get source` finds the same
# Mesa the machine runs. Written once, by root.
ensure_deb_src() {
    local list=/etc/apt/sources.list.d/probebench-mesa-src.sources
    if apt-cache showsrc mesa 2>/dev/null | grep -q '^Package: mesa'; then return 0; fi
    [ "$(id -u)" -eq 0 ] || die "no deb-src entry for Mesa; as root this script adds $list"
    local uri suites comps
    uri=$(grep -h -m1 '^URIs:.*debian/*$' /etc/apt/sources.list.d/*.sources 2>/dev/null \
        | awk '{print $2}' || true)
    uri=${uri:-http://deb.debian.org/debian}
    suites=$(. /etc/os-release; echo "${VERSION_CODENAME:-bookworm} ${VERSION_CODENAME:-bookworm}-updates")
    comps=main
    printf 'Types: deb-src\nURIs: %s\nSuites: %s\nComponents: %s\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
        "$uri" "$suites" "$comps" > "$list"
    apt-get update -q >/dev/null || { rm -f "$list"; die "apt-get update failed with the deb-src entry (no network to $uri?)"; }
}

main() {
    local print_only=0
    case "${1:-}" in
        --print) print_only=1 ;;
        -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; return 0 ;;
        "") ;;
        *) die "unknown option '$1' (try --help)" ;;
    esac
    local dest
    dest=$(cache_dir)
    if [ $print_only -eq 1 ]; then
        echo "$dest"
        [ -f "$dest/complete" ]
        return
    fi
    if [ -f "$dest/complete" ]; then
        echo "==> mesa-shim: up to date in $dest"
        return 0
    fi
    install_build_packages
    ensure_deb_src
    local root
    root=$(dirname "$dest")
    mkdir -p "$root" || die "cannot create the cache folder $root"
    # Global, not local: the EXIT trap runs after main has returned.
    work=$(mktemp -d "${TMPDIR:-/tmp}/pb-mesa-shim.XXXXXX")
    chmod 755 "$work" # apt-get source downloads as _apt where it can
    trap 'rm -rf "$work"' EXIT
    local free_kib
    free_kib=$(df -Pk "$work" | awk 'NR==2 {print $4}')
    [ "$free_kib" -ge 1500000 ] || die "needs 1.5 GB free in $work, has $((free_kib / 1024)) MB"
    local version upstream
    version=$(mesa_version)
    upstream=${version%%-*}
    echo "==> mesa-shim: fetching Debian's mesa $version source into $work"
    (cd "$work" && apt-get source -q --download-only "mesa=$version" >/dev/null) \
        || die "apt-get source mesa=$version failed (deb-src reachable?)"
    # The orig tarball is Mesa's release; Debian's patches do not touch the compilers.
    local orig
    orig=$(ls "$work"/mesa_"${upstream#*:}".orig.tar.* 2>/dev/null | head -1)
    [ -n "$orig" ] || die "no orig tarball for mesa $version in $work"
    tar -C "$work" -xf "$orig"
    local src
    src=$(find "$work" -maxdepth 1 -type d -name 'mesa-*' | head -1)
    [ -n "$src" ] || die "the orig tarball $orig held no mesa-* folder"
    echo "==> mesa-shim: building $PB_MESA_DRIVERS with drm-shim (5-10 min on 2 cores)"
    local stage="$dest.partial.$$"
    rm -rf "$stage"
    # Debian's python3 has mako; a python earlier on PATH (pyenv) may not. The prefix is the
    # cache folder itself (the libraries' built-in search paths point there); DESTDIR stages it.
    PATH=/usr/bin:/bin meson setup "$work/build" "$src" --prefix="$dest" --libdir=lib \
        "${PB_MESA_OPTIONS[@]}" > "$work/configure.log" 2>&1 \
        || { tail -30 "$work/configure.log" >&2; die "meson setup failed (log above)"; }
    PATH=/usr/bin:/bin DESTDIR="$work/destdir" ninja -C "$work/build" -j"$(nproc)" install \
        > "$work/build.log" 2>&1 \
        || { tail -30 "$work/build.log" >&2; die "the Mesa build failed (log above)"; }
    cp -a "$work/destdir$dest" "$stage" || { rm -rf "$stage"; die "cannot write $stage"; }
    for shim in freedreno panfrost v3d nouveau; do
        [ -f "$stage/lib/lib${shim}_noop_drm_shim.so" ] \
            || { rm -rf "$stage"; die "the build made no $shim shim (lib${shim}_noop_drm_shim.so)"; }
    done
    printf 'mesa %s\ndrivers %s\nbuilt %s\n' "$version" "$PB_MESA_DRIVERS" "$(date -u +%FT%TZ)" \
        > "$stage/complete"
    rm -rf "$dest"
    mv "$stage" "$dest"
    echo "==> mesa-shim: installed into $dest"
}

main "$@"
