#!/usr/bin/env bash
# usage: tools/run.sh [MODEL] [anisomesh mesh options]
# Installs what is missing (apt-get), builds Release, meshes MODEL (default: the bracket in
# models/) and prints the run's summary (the JSON report is written beside the mesh).
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
"$here/tools/setup.sh" || exit 1
"$here/tools/build.sh" anisomesh || exit 1   # the program only, not the test suite
model=${1:-$here/models/bracket.step}
[ $# -gt 0 ] && shift
out=${ANISOMESH_OUT:-$here/build/out}
mkdir -p "$out"
name=$(basename "$model"); name=${name%.*}
"$here/build/anisomesh" mesh "$model" -o "$out/$name.msh" --report "$out/$name.report.json" "$@"
rc=$?
[ -f "$out/$name.report.json" ] && echo "report: $out/$name.report.json" >&2
exit $rc
