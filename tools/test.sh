#!/usr/bin/env bash
# usage: tools/test.sh [ctest options]   (e.g. -L slow for the slow tier)
# Installs what is missing (apt-get), builds Release, runs the test suite with ctest.
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/tools/setup.sh" --with-freecad || exit 1   # FreeCAD: the macro and UNV import tests
"$here/tools/build.sh" || exit 1
[ $# -eq 0 ] && set -- -LE slow   # the fast tiers by default
cd "$here/build" && ctest --output-on-failure -j"$(nproc 2>/dev/null || echo 2)" "$@"
