#!/usr/bin/env bash
# Installs the Debian packages facet builds, tests and runs with, on Debian 12
# (bookworm) or 13 (trixie): the few names that differ are picked from
# /etc/os-release. Idempotent: it asks apt only for what dpkg says is missing.
set -euo pipefail

# shellcheck disable=SC1091
. /etc/os-release
case "${VERSION_ID:-}" in
  12) clang_rt=libclang-rt-14-dev ;;  # bookworm's clang 14 ships its runtimes under a versioned name
  13) clang_rt=libclang-rt-dev ;;     # trixie's default clang (19) has an unversioned one
  *) echo "install-deps: Debian 12 or 13 expected, /etc/os-release says '${PRETTY_NAME:-unknown}'" >&2; exit 1 ;;
esac

packages=(
  build-essential cmake pkg-config
  libglm-dev             # vectors and matrices under the course math
  libtinygltf-dev        # glTF 2.0 parser (its implementation lives in libtinygltf.so)
  nlohmann-json3-dev     # RenderSettings <-> JSON
  libstb-dev             # PNG read/write (stb_image, stb_image_write in libstb.so)
  libcli11-dev           # command-line parsing
  doctest-dev            # unit tests
  libosmesa6-dev         # headless OpenGL on llvmpipe
  python3-glad           # glad 2: generates the OpenGL 4.5 core loader at build time (renderer/gl/CMakeLists.txt)
  libegl-dev libgl-dev libgl1-mesa-dri libegl-mesa0  # EGL surfaceless, the second headless context
  libglfw3-dev libimgui-dev                          # the interactive viewer
  xvfb xauth             # the viewer's tests run in a virtual X server
  assimp-testmodels      # real glTF 2.0 files (well-formed and broken) for the tests
  libteem-dev            # NRRD volumes (teem is the format's reference library)
  zlib1g-dev             # zlib: PNG writing (image/png.cpp), and the gzFile type of teem's gzip stream, which the NRRD reader closes itself
  libnifti2-dev          # NIfTI-1 volumes (the NIfTI group's niftiio)
  python3-nibabel        # a small anatomical MRI (nibabel/tests/data/anatomical.nii) the volume tests read
  libembree-dev          # Intel Embree (3 on Debian 12, 4 on 13): the peer facet bench measures the ray tracer's BVH against
  clang "$clang_rt"       # libFuzzer and its sanitizer runtimes (scripts/fuzz.sh)
  help2man               # the man page, written from facet --help (packaging/man_page.sh)
  file dpkg-dev          # the .deb's Depends, computed from its binaries by CPack's dpkg-shlibdeps (which needs file) on each release
  libxml2-utils          # xmllint: the test that facet batch's JUnit report is well-formed XML (tests/cli/batch_run.cmake)
  python3-yaml           # the test that reads docs/batch.md's Kubernetes Job (tests/cli/batch_docs.py)
  python3-junitparser    # a JUnit consumer: the test that reads facet batch's report with it (tests/cli/junit_consumer.py)
  openimageio-tools      # OpenImageIO's idiff: only the test that cross-checks facet diff against it (tests/compare/idiff_crosscheck.cpp)
  qemu-user              # CPUs without AVX2 or AVX-512, emulated: the tests that the wide code is chosen at run time (tests/cpu/emulated_lanes.cmake)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
"${as_root[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
