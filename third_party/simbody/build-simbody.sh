#!/usr/bin/env bash
# Builds Simbody 3.7 from Debian's own source package, in Release (-O2 -DNDEBUG),
# with rockroll's patches (patches/*.patch, applied in name order), and installs it
# into PREFIX. Debian's binary libsimbody is built without NDEBUG, which leaves every
# container check on and was measured about 2x slower (bench/README.md).
#
#   third_party/simbody/build-simbody.sh WORKDIR
#
# WORKDIR receives src/, build/ and install/ (the prefix CMake is pointed at).
# Cached: nothing is rebuilt while install/rockroll-simbody.stamp matches the version,
# the flags, this script and every patch. A patch that does not apply stops the build.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mkdir -p "${1:?usage: build-simbody.sh WORKDIR}" && cd "$1" && pwd)"
version="3.7+dfsg"
prefix="$work/install"
stamp="$prefix/rockroll-simbody.stamp"

want="simbody $version Release NDEBUG $(cat "$0" "$here"/patches/*.patch | sha256sum | cut -c1-16)"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want" ]; then
  exit 0
fi
echo "build-simbody.sh: building Simbody $version (Release, with $(ls "$here"/patches/*.patch | wc -l) patches) into $prefix; a few minutes, once" >&2

SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
# apt-get source needs a deb-src entry for the suite the binaries come from.
if ! apt-get source --print-uris -qq "simbody=3.7+dfsg-3" >/dev/null 2>&1; then
  echo "build-simbody.sh: adding a deb-src entry for bookworm (/etc/apt/sources.list.d/rockroll-deb-src.sources)" >&2
  $SUDO tee /etc/apt/sources.list.d/rockroll-deb-src.sources >/dev/null <<'SRC'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
  $SUDO apt-get update -qq
fi

rm -rf "$work/src" "$work/build" "$prefix"
mkdir -p "$work/src"
( cd "$work/src" && apt-get source -qq "simbody=3.7+dfsg-3" >/dev/null 2>&1 ) || {
  echo "build-simbody.sh: 'apt-get source simbody=3.7+dfsg-3' failed in $work/src" >&2; exit 1; }
srcdir="$work/src/simbody-$version"
[ -f "$srcdir/CMakeLists.txt" ] || { echo "build-simbody.sh: no $srcdir/CMakeLists.txt after apt-get source" >&2; exit 1; }

for p in "$here"/patches/*.patch; do
  if ! patch -d "$srcdir" -p1 --forward --batch --fuzz=0 --quiet < "$p"; then
    echo "build-simbody.sh: patch $(basename "$p") does not apply to simbody $version; fix or remove it" >&2
    exit 1
  fi
  echo "build-simbody.sh: applied $(basename "$p")" >&2
done

log="$work/build.log"
fail() { tail -40 "$log" >&2; echo "build-simbody.sh: $1 failed; full log: $log" >&2; exit 1; }
cmake -S "$srcdir" -B "$work/build" -G Ninja \
  -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_INSTALL_PREFIX="$prefix" \
  -DCMAKE_INSTALL_LIBDIR=lib \
  -DBUILD_VISUALIZER=OFF -DBUILD_EXAMPLES=OFF -DBUILD_TESTING=OFF -DINSTALL_DOCS=OFF \
  -DBUILD_STATIC_LIBRARIES=OFF \
  -DSIMBODY_VISUALIZER_INSTALL_DIR="$prefix/libexec/simbody" >"$log" 2>&1 || fail "configuring Simbody"
cmake --build "$work/build" -j"$(nproc)" >>"$log" 2>&1 || fail "building Simbody"
cmake --install "$work/build" >>"$log" 2>&1 || fail "installing Simbody"
echo "$want" > "$stamp"
echo "build-simbody.sh: Simbody installed in $prefix" >&2
