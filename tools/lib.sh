# Shared helpers for the tools/ scripts. Sourced, never run.
#
# Everything Firmament needs on Linux lives in one Debian sid sysroot inside a cache folder
# outside the checkout. Commands run inside it through bubblewrap, so nothing stays mounted
# or running after they end (docs/building.md, "The sysroot").

set -euo pipefail

FIRMAMENT_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
FIRMAMENT_CACHE=${FIRMAMENT_CACHE:-${XDG_CACHE_HOME:-${HOME:-/var/cache}/.cache}/firmament}
FIRMAMENT_MIRROR=${FIRMAMENT_MIRROR:-http://deb.debian.org/debian}

log() { printf '[firmament] %s\n' "$*" >&2; }
die() { printf '[firmament] error: %s\n' "$*" >&2; exit 1; }

# The Direct3D 11 implementation the Windows programs run on under Wine (docs/building.md, "Two
# Direct3D 11 implementations"): wined3d, Wine's own over OpenGL on llvmpipe (the default), or
# dxvk, DXVK over Vulkan on Mesa's lavapipe. tools/demo, tools/test and tools/bench take
# --d3d11 NAME; tools/sandbox/wine-env picks the prefix and the DLLs by it.
# Exported: a tool another tool runs (tools/test runs tools/demo) keeps the choice.
# FIRMAMENT_D3D11_GIVEN: 1 when the caller chose (the variable set, or --d3d11 given).
FIRMAMENT_D3D11_GIVEN=${FIRMAMENT_D3D11:+1}
export FIRMAMENT_D3D11=${FIRMAMENT_D3D11:-wined3d}
# The Vulkan driver DXVK gets: lavapipe (empty, the default), or "host", the host's GPU through
# Mesa's hardware drivers (radv for AMD, anv and hasvk for Intel, nvk for NVIDIA), with the GPU's
# device nodes bound into the sandbox. tools/demo sets it for --hardware or --adapter under DXVK.
FIRMAMENT_VULKAN=${FIRMAMENT_VULKAN:-}
check_d3d11() {
    case "$FIRMAMENT_D3D11" in
        wined3d | dxvk) ;;
        *) die "--d3d11 $FIRMAMENT_D3D11: no such Direct3D 11 implementation (wined3d or dxvk)" ;;
    esac
}
# take_d3d11_option ARGS...: sets FIRMAMENT_D3D11 from a --d3d11 NAME (or --d3d11=NAME) among the
# arguments, and leaves the other arguments, in order, in the array ARGUMENTS.
take_d3d11_option() {
    ARGUMENTS=()
    while [ "$#" -gt 0 ]; do
        case "$1" in
            --d3d11)
                [ "$#" -ge 2 ] || die "--d3d11 needs a name: wined3d or dxvk"
                FIRMAMENT_D3D11=$2
                FIRMAMENT_D3D11_GIVEN=1
                shift 2
                ;;
            --d3d11=*) FIRMAMENT_D3D11=${1#--d3d11=}; FIRMAMENT_D3D11_GIVEN=1; shift ;;
            *) ARGUMENTS+=("$1"); shift ;;
        esac
    done
    check_d3d11
}

# step "description" command...: runs a command, printing what it does and how long it took.
step() {
    local what=$1; shift
    local start=$SECONDS
    log "$what ..."
    "$@"
    log "$what: done in $((SECONDS - start)) s"
}

# The sysroot's key: a hash of the package list, whose first line also carries a format
# number that is raised when tools/sysroot/create changes what it puts into the sysroot.
# A new key gives a new sysroot (the old one is removed once the new one is complete).
sysroot_key() {
    sha256sum <"$FIRMAMENT_ROOT/tools/sysroot/packages.txt" | cut -c1-12
}

# The third-party prefix's key: a change of the script that cross-builds it, or of the
# toolchain file, rebuilds the prefix inside the same sysroot.
third_party_key() {
    cat "$FIRMAMENT_ROOT/tools/sysroot/build-third-party" \
        "$FIRMAMENT_ROOT/cmake/toolchains/mingw-w64-posix.cmake" |
        sha256sum | cut -c1-12
}

# The portable build's native packages are a stage of their own, keyed by their list's hash.
portable_key() { sha256sum <"$FIRMAMENT_ROOT/tools/sysroot/packages-portable.txt" | cut -c1-12; }

sysroot_ready() {
    [ "$(cat "$(sysroot_dir)/.firmament-complete" 2>/dev/null)" = "$(third_party_key)" ] &&
        [ "$(cat "$(sysroot_dir)/.stamp-portable" 2>/dev/null)" = "$(portable_key)" ]
}

sysroot_dir() { printf '%s/sysroot-%s' "$FIRMAMENT_CACHE" "$(sysroot_key)"; }

# in_sysroot [--display] CMD...: runs CMD inside the sysroot with the checkout at /src (and the
# bubblewrap arguments in the array FIRMAMENT_EXTRA_BINDS, when set).
# --unshare-pid and --die-with-parent end every process started inside (Xvfb, wineserver)
# together with the command, also on failure or Ctrl-C.
in_sysroot() {
    local pass_display=0
    if [ "${1:-}" = "--display" ]; then pass_display=1; shift; fi
    local root
    root=$(sysroot_dir)
    sysroot_ready || die "sysroot $root is not complete: run tools/sysroot/create"
    mkdir -p "$FIRMAMENT_CACHE/ccache" "$FIRMAMENT_CACHE/shader-cache" "$FIRMAMENT_CACHE/tables"
    local args=(
        --bind "$root" /
        --proc /proc --dev /dev --tmpfs /tmp
        --ro-bind /etc/resolv.conf /etc/resolv.conf
        --bind "$FIRMAMENT_ROOT" /src
        --unshare-pid --die-with-parent
        --chdir /src
        --setenv HOME /root
        --setenv PATH /usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin
        --setenv LANG C.UTF-8
        --setenv FIRMAMENT_D3D11 "$FIRMAMENT_D3D11"
        --unsetenv DISPLAY --unsetenv XAUTHORITY
        # The compiler cache (cmake/FirmamentCompilerCache.cmake) lives in the cache folder, so
        # that it outlives a checkout. Its objects are keyed by the contents of the source and
        # its headers, so the sloppiness the precompiled headers need (their #defines and
        # __TIME__, and the times of headers a fresh clone has just written) keeps hits exact.
        --bind "$FIRMAMENT_CACHE/ccache" /var/cache/ccache
        --setenv CCACHE_DIR /var/cache/ccache
        --setenv CCACHE_MAXSIZE 4G
        --setenv CCACHE_SLOPPINESS pch_defines,time_macros,include_file_mtime,include_file_ctime
        # The compiled shaders' cache (cmake/shader-cache.sh), beside it.
        --bind "$FIRMAMENT_CACHE/shader-cache" /var/cache/firmament-shaders
        --setenv FIRMAMENT_SHADER_CACHE /var/cache/firmament-shaders
        # The program's table cache under Wine (tools/sandbox/session), shared by checkouts.
        --bind "$FIRMAMENT_CACHE/tables" /var/cache/firmament-tables
        --setenv FIRMAMENT_TABLE_CACHE /var/cache/firmament-tables
    )
    # Host folders and files a command names outside the checkout (tools/demo's path arguments),
    # bound at their own paths.
    args+=(${FIRMAMENT_EXTRA_BINDS[@]+"${FIRMAMENT_EXTRA_BINDS[@]}"})
    # The host's GPU: its render nodes, and /sys, where Mesa's drivers read the devices' PCI ids.
    if [ "$FIRMAMENT_VULKAN" = host ]; then
        args+=(--dev-bind /dev/dri /dev/dri --ro-bind /sys /sys --setenv FIRMAMENT_VULKAN host)
    fi
    if [ "$pass_display" = 1 ] && [ -n "${DISPLAY:-}" ]; then
        args+=(--bind /tmp/.X11-unix /tmp/.X11-unix --setenv DISPLAY "$DISPLAY")
        if [ -n "${XAUTHORITY:-}" ] && [ -f "$XAUTHORITY" ]; then
            args+=(--ro-bind "$XAUTHORITY" /tmp/.Xauthority --setenv XAUTHORITY /tmp/.Xauthority)
        fi
    fi
    [ -t 0 ] || args+=(--new-session)
    bwrap "${args[@]}" "$@"
}

require_root() {
    [ "$(id -u)" = 0 ] || die "this needs root (debootstrap and bubblewrap mount file systems); run it as root"
}

# Installs a host package from the host's own archive (the only change made to the host).
require_host_tool() {
    local tool=$1 package=$2
    command -v "$tool" >/dev/null 2>&1 && return 0
    require_root
    log "installing $package from the host's archive"
    apt-get update -qq >/dev/null || die "apt-get update failed: is the Debian archive reachable?"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$package" >/dev/null ||
        die "could not install $package from the host's archive"
}

# Makes sure the sysroot exists, creating it when missing (idempotent).
ensure_sysroot() {
    require_root
    require_host_tool bwrap bubblewrap
    sysroot_ready || "$FIRMAMENT_ROOT/tools/sysroot/create"
}

# build_portable: configures and builds the 'portable' preset (the platform-independent code
# natively with clang, ASan and UBSan, and the fuzz targets) into build/portable.
build_portable() {
    in_sysroot bash -c 'cmake --preset portable >build-portable-configure.log 2>&1 ||
                            { cat build-portable-configure.log >&2; rm -f build-portable-configure.log; exit 1; }
                        rm -f build-portable-configure.log
                        ninja -C build/portable -t recompact >/dev/null
                        cmake --build --preset portable'
}
