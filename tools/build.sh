#!/usr/bin/env bash
# usage: tools/build.sh [TARGET...]   (default: everything, tests included)
# Configures and builds anisomesh (Release) in build/. Used by run.sh (the program only) and test.sh.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc 2>/dev/null || echo 2)
launcher=()
if command -v ccache > /dev/null; then   # optional: faster rebuilds, shared across checkouts
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$(dirname "$here")}
fi
cmake -S "$here" -B "$here/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" > "$here/build.log" 2>&1 || { cat "$here/build.log" >&2; exit 1; }
targets=(); for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$here/build" -j"$jobs" "${targets[@]}" >> "$here/build.log" 2>&1 || { tail -60 "$here/build.log" >&2; exit 1; }
