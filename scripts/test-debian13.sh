#!/usr/bin/env bash
# Builds facet and runs its tests on Debian 13 (trixie), in a chroot, from a
# clean clone of this repository's HEAD, with the README's commands:
# install-deps.sh, then the build, then ctest. Run as root (debootstrap,
# chroot and mount need it); .ci/run calls it after the Debian 12 stages.
#
#   scripts/test-debian13.sh [CTEST ARGS...]
#
# With no arguments it runs the quick tier and the agreement suite when the
# suite has those labels, and every test otherwise. What it keeps between
# runs, under FACET_DEBIAN13_DIR (default /var/tmp/facet-debian13), is only
# what a fresh machine makes again by itself: the chroot (debootstrap'd
# once, marked complete only when it is; install-deps.sh brings it up to
# date on every run) and a ccache folder (a cache: a miss only costs time).
set -euo pipefail
cd "$(dirname "$0")/.."
repo=$(pwd)
work=${FACET_DEBIAN13_DIR:-/var/tmp/facet-debian13}
root="$work/root"
start=$(date +%s)
say() { echo "debian13: $* ($(($(date +%s) - start)) s)"; }

[ "$(id -u)" -eq 0 ] || { echo "debian13: run as root (debootstrap, chroot and mount need it)" >&2; exit 1; }

# The Debian archive this machine already uses (deb822 or one-line sources).
mirror=$(grep -hoE '^(URIs:|deb) +https?://[^ ]+/debian/?( |$)' /etc/apt/sources.list /etc/apt/sources.list.d/*.sources /etc/apt/sources.list.d/*.list 2>/dev/null |
  grep -oE 'https?://[^ ]+' | head -n 1 || true)
mirror=${mirror:-http://deb.debian.org/debian}

if [ ! -e "$root/.facet-complete" ]; then
  command -v debootstrap >/dev/null || { apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap >/dev/null; }
  rm -rf "$root"
  mkdir -p "$work"
  say "debootstrap trixie from $mirror"
  debootstrap --variant=minbase trixie "$root" "$mirror" >"$work/debootstrap.log" 2>&1 ||
    { tail -n 20 "$work/debootstrap.log" >&2; echo "debian13: debootstrap failed (log: $work/debootstrap.log)" >&2; exit 1; }
  touch "$root/.facet-complete"
fi

# A clean clone of HEAD: nothing of this work tree's build or untracked files.
rm -rf "$root/facet"
git clone -q --no-hardlinks "$repo" "$root/facet"
say "cloned $(git -C "$root/facet" rev-parse --short HEAD)"

# Inside a private mount namespace, so that /proc, /sys and /dev leave with it.
unshare --mount --propagation private bash -euo pipefail -s -- "$root" "$@" <<'INSIDE'
root=$1; shift
mount -t proc proc "$root/proc"
mount --rbind /sys "$root/sys"
mount --rbind /dev "$root/dev"
chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 CCACHE_DIR=/var/cache/facet-ccache \
  bash -euo pipefail -s -- "$@" <<'CHROOT'
cd /facet
. /etc/os-release
echo "debian13: inside $PRETTY_NAME"
./scripts/install-deps.sh
command -v ccache >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends ccache >/dev/null
./scripts/build.sh -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache >/dev/null
ccache --show-stats 2>/dev/null | grep -iE '^(cacheable|hits|misses)|hit' | head -n 3 || true
if [ $# -gt 0 ]; then
  ctest --test-dir build --output-on-failure --parallel "$(nproc)" "$@"
elif [ -n "$(ctest --test-dir build -N -L quick 2>/dev/null | grep -E '^ +Test +#')" ]; then
  ctest --test-dir build --output-on-failure --parallel "$(nproc)" -L quick
  ctest --test-dir build --output-on-failure --parallel "$(nproc)" -L agreement
else
  ctest --test-dir build --output-on-failure --parallel "$(nproc)"
fi
CHROOT
INSIDE
say "done"
