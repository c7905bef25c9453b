#!/usr/bin/env bash
# Installs the Debian packages candela builds with (none are vendored or downloaded). Idempotent: installs only what is missing,
# runs `apt-get update` only then, and is quiet when everything is already present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ccache
  libembree-dev libtbb-dev libopenexr-dev libstb-dev libtinyobjloader-dev
  nlohmann-json3-dev libcli11-dev libfmt-dev libgtest-dev libgmock-dev libbenchmark-dev
  # gzip-compressed PLY meshes (.ply.gz) and Loop subdivision (pbrt-v4's plymesh, loopsubdiv).
  zlib1g-dev libosd-dev
  # OpenVDB volume grids (.vdb); its headers need Boost's, which libopenvdb-dev does not depend on.
  libopenvdb-dev libboost-dev
  # Rendering one image on many machines (mpirun candela render, docs/CLUSTER.md).
  libopenmpi-dev openmpi-bin
  # The Python module (python/, README.md "Python"): pybind11 for the extension; numpy for its
  # arrays, pytest for its tests, matplotlib for its example.
  python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib
  # The sanitizer and fuzzing build (scripts/sanitize.sh, scripts/fuzz.sh): clang 14, its
  # ASan/UBSan/libFuzzer runtimes (only recommended by clang, so named here) and
  # llvm-symbolizer for readable sanitizer reports.
  clang libclang-rt-14-dev llvm
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
echo "setup: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
