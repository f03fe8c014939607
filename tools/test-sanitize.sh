#!/usr/bin/env bash
# usage: tools/test-sanitize.sh [ctest options]   (default: the fast tier, -LE slow)
# Like tools/test.sh, for the sanitizer build (docs/development.md, "Sanitizers"): installs
# what is missing, builds Debug with ANISOMESH_SANITIZE=ON (AddressSanitizer, LeakSanitizer,
# UBSan, libstdc++ assertions, ANISO_ASSERT; CMakeLists.txt) in build-sanitize/ (or
# $ANISOMESH_SANITIZE_BUILD), runs ctest with the sanitizers' options set here.
#
# Every sanitizer report goes to a file of build-sanitize/sanitizer-logs/ (log_path), also
# those of processes whose stderr nobody reads: the CAD child process (cad/ChildProcess.cpp)
# sends its stderr to /dev/null, and a child that stops on a report is only a "failed"
# preparation to its parent. The script fails when a test fails or when any report was
# written, and prints the reports. OCCT, Python, Gmsh, FreeCAD are not instrumented; the
# suppressions of tools/sanitize/ cover only their code.
set -uo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
build=${ANISOMESH_SANITIZE_BUILD:-$here/build-sanitize}
jobs=$(nproc 2>/dev/null || echo 2)
"$here/tools/setup.sh" --with-freecad || exit 1
mkdir -p "$build"
log=$build/build.log
start=$(date +%s)
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DANISOMESH_SANITIZE=ON -DANISOMESH_BUILD_BENCH=OFF > "$log" 2>&1 || { cat "$log" >&2; exit 1; }
cmake --build "$build" -j"$jobs" >> "$log" 2>&1 || { tail -60 "$log" >&2; exit 1; }
echo "test-sanitize: built in $(( $(date +%s) - start )) s" >&2

logs=$build/sanitizer-logs
rm -rf "$logs" && mkdir -p "$logs"
supp=$here/tools/sanitize
# halt_on_error: the first report ends the process (with -fno-sanitize-recover=undefined, UB
# too); detect_leaks at exit; the CAD child ends with _exit (no leak check there).
export ASAN_OPTIONS="log_path=$logs/asan:halt_on_error=1:detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_invalid_pointer_pairs=0:print_suppressions=0"
export UBSAN_OPTIONS="log_path=$logs/ubsan:halt_on_error=1:print_stacktrace=1:suppressions=$supp/ubsan.supp"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
[ $# -eq 0 ] && set -- -LE slow   # the fast tiers by default
start=$(date +%s)
(cd "$build" && ctest --output-on-failure -j"$jobs" "$@")
rc=$?
echo "test-sanitize: ctest in $(( $(date +%s) - start )) s" >&2
reports=$(find "$logs" -type f | sort)
if [ -n "$reports" ]; then
  echo "test-sanitize: $(echo "$reports" | wc -l) sanitizer report(s):" >&2
  for f in $reports; do echo "==== $f" >&2; cat "$f" >&2; done
  rc=1
fi
exit $rc
