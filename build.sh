#!/usr/bin/env bash
# Installs the Debian packages rockroll needs (when missing) and builds it into
# build/. Used by both commands of the README.
set -euo pipefail
cd "$(dirname "$0")"

packages=(build-essential cmake libsimbody-dev libeigen3-dev libtomlplusplus-dev libcli11-dev
          libfmt-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev libsundials-dev libssl-dev python3-matplotlib)
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

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" >&2
