#!/usr/bin/env bash
# Installs the Debian packages rockroll needs (when missing), builds Simbody 3.7 in
# Release from Debian's source package once (third_party/simbody/build-simbody.sh,
# cached in build/third_party/simbody), and builds rockroll into build/. Used by both
# commands of the README.
#   ./build.sh [TARGET...]                  builds everything, or only the CMake targets
#                                           named (the README's first command builds `rockroll`)
#   ROCKROLL_SYSTEM_SIMBODY=ON ./build.sh   links Debian's libsimbody-dev instead
#                                           (built without NDEBUG; measured ~2x slower)
set -euo pipefail
cd "$(dirname "$0")"
system_simbody="${ROCKROLL_SYSTEM_SIMBODY:-OFF}"

if [ "$system_simbody" = "ON" ]; then
  simbody_packages=(libsimbody-dev)
else
  # Simbody's own build needs LAPACK/BLAS; apt-get source needs dpkg-dev.
  simbody_packages=(liblapack-dev libblas-dev dpkg-dev patch xz-utils)
fi
packages=("${simbody_packages[@]}" build-essential cmake ninja-build libeigen3-dev libtomlplusplus-dev libcli11-dev
          libfmt-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev libsundials-dev libssl-dev libtbb-dev
          python3-matplotlib pybind11-dev python3-dev python3-numpy python3-pytest parallel)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "build.sh: installing ${missing[*]}" >&2
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

if [ "$system_simbody" != "ON" ]; then
  third_party/simbody/build-simbody.sh build/third_party/simbody
fi
# Ninja schedules every object of every target on both cores (Make waits for each
# library before compiling the objects that use it). A build/ made earlier with
# another generator keeps it: CMake refuses to switch generators in place.
generator=(-G Ninja)
[ -f build/CMakeCache.txt ] && generator=()
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DROCKROLL_SYSTEM_SIMBODY="$system_simbody" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}" >&2
