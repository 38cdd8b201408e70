#!/usr/bin/env bash
# Builds Simbody's own test suite from the patched source build-simbody.sh prepared
# (Release, -O2 -DNDEBUG, every patch in patches/ applied) and runs it, so each patch
# is checked against Simbody's tests (CPodes, integrators, constraints, ...).
#
#   third_party/simbody/test-simbody.sh WORKDIR
#
# WORKDIR is build-simbody.sh's (./build.sh uses build/third_party/simbody); the script
# runs build-simbody.sh on it first (a no-op when its install is current), builds the
# tests in WORKDIR/build-tests and writes ctest's output to WORKDIR/tests.log.
# Exit status: 0 when every test passes, 1 otherwise. The result with today's patches
# is recorded in bench/README.md ("Simbody's own tests").
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mkdir -p "${1:?usage: test-simbody.sh WORKDIR}" && cd "$1" && pwd)"
"$here/build-simbody.sh" "$work"
srcdir="$work/src/simbody-3.7+dfsg"
[ -f "$srcdir/CMakeLists.txt" ] || { echo "test-simbody.sh: no patched source in $srcdir (remove $work/install and rerun)" >&2; exit 1; }
log="$work/tests.log"
echo "test-simbody.sh: building Simbody's tests in $work/build-tests (Release, $(ls "$here"/patches/*.patch | wc -l) patches); many minutes" >&2
cmake -S "$srcdir" -B "$work/build-tests" -G Ninja \
  -DCMAKE_BUILD_TYPE=Release \
  -DBUILD_VISUALIZER=OFF -DBUILD_EXAMPLES=OFF -DBUILD_TESTING=ON -DINSTALL_DOCS=OFF \
  -DBUILD_STATIC_LIBRARIES=OFF \
  -DSIMBODY_VISUALIZER_INSTALL_DIR="$work/build-tests/libexec/simbody" >"$log" 2>&1 || { tail -40 "$log" >&2; echo "test-simbody.sh: configuring failed; log: $log" >&2; exit 1; }
cmake --build "$work/build-tests" -j"$(nproc)" >>"$log" 2>&1 || { tail -40 "$log" >&2; echo "test-simbody.sh: building the tests failed; log: $log" >&2; exit 1; }
status=0
ctest --test-dir "$work/build-tests" -j"$(nproc)" --output-on-failure >>"$log" 2>&1 || status=1
grep -E "tests passed|tests failed" "$log" | tail -1
[ "$status" -eq 0 ] || { grep -A200 "The following tests FAILED" "$log" >&2 || true; echo "test-simbody.sh: failures; log: $log" >&2; }
exit "$status"
