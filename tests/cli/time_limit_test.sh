#!/bin/bash
# --time-limit (issue 20, "never hang"): a run stopped by its limit exits 3 with one line
# naming the limit and the phase, writes its report with status failed and no mesh; a
# generous limit changes nothing (byte-identical mesh).
# usage: time_limit_test.sh CLI SHARED_DIR
cli=$1; shared=$2
cube=$shared/bench/cube_1.step
big=$shared/assemblies/NEO.step   # 3.5 MB: several seconds to read
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
pass=0; fail=0
result() { if [ -z "$2" ]; then pass=$((pass+1)); echo "ok $1"; else fail=$((fail+1)); echo "FAIL $1: $2"; fi; }

# 1: a run of several seconds (290k tets) stopped after 0.3 s.
start=$(date +%s.%N)
timeout 120 "$cli" mesh "$cube" --size 0.025 -o "$t/stopped.msh" --report "$t/stopped.json" --time-limit 0.3 \
  > "$t/so" 2> "$t/se"; rc=$?
took=$(echo "$(date +%s.%N) - $start" | bc)
why=""
[ $rc -eq 3 ] || why="exit $rc (want 3)"
[ -z "$why" ] && [ "$(wc -l < "$t/se")" -ne 1 ] && why="not one line: $(cat "$t/se")"
[ -z "$why" ] && ! grep -q "stopped after the time limit of 0.3 s during [a-z]" "$t/se" && why="message: $(cat "$t/se")"
[ -z "$why" ] && [ -e "$t/stopped.msh" ] && why="left a mesh file"
[ -z "$why" ] && ls "$t" | grep -q '\.tmp' && why="left a temporary file"
[ -z "$why" ] && ! /usr/bin/python3 -c "
import json, sys
r = json.load(open('$t/stopped.json'))
sys.exit(0 if r['status'] == 'failed' and 'time limit' in r['failures'][0]['what'] else 1)" && why="report: $(head -c 300 "$t/stopped.json")"
# the whole run takes several seconds; stopped, it ends soon after its limit (a loaded machine: 10 s)
[ -z "$why" ] && [ "$(echo "$took > 10" | bc)" -eq 1 ] && why="took $took s"
result "tiny limit: $(cat "$t/se")" "$why"

# 2: a limit hit while reading names that phase.
timeout 120 "$cli" mesh "$cube" -o "$t/r.msh" --time-limit 0.001 > /dev/null 2> "$t/se"; rc=$?
why=""
[ $rc -eq 3 ] || why="exit $rc (want 3)"
[ -z "$why" ] && ! grep -q "during reading" "$t/se" && why="message: $(cat "$t/se")"
[ -z "$why" ] && [ -e "$t/r.msh" ] && why="left a mesh file"
result "limit while reading" "$why"

# 2b: a read still running at the limit is killed (it runs in a child process), soon,
# leaving no temporary folder.
mkdir "$t/tmp"
start=$(date +%s.%N)
TMPDIR=$t/tmp timeout 120 "$cli" mesh "$big" -o "$t/big.msh" --time-limit 0.3 > /dev/null 2> "$t/se"; rc=$?
took=$(echo "$(date +%s.%N) - $start" | bc)
why=""
[ $rc -eq 3 ] || why="exit $rc (want 3)"
[ -z "$why" ] && ! grep -q "time limit of 0.3 s during reading" "$t/se" && why="message: $(cat "$t/se")"
[ -z "$why" ] && [ "$(echo "$took > 3" | bc)" -eq 1 ] && why="took $took s"
[ -z "$why" ] && [ -n "$(ls "$t/tmp")" ] && why="left $(ls "$t/tmp")"
result "limit during a long read: killed after $took s" "$why"

# 3: a generous limit changes nothing.
timeout 120 "$cli" mesh "$cube" --size 0.05 -o "$t/free.msh" -q; rc1=$?
timeout 120 "$cli" mesh "$cube" --size 0.05 -o "$t/limited.msh" -q --time-limit 600; rc2=$?
why=""
[ $rc1 -eq 0 ] && [ $rc2 -eq 0 ] || why="exit $rc1 / $rc2"
[ -z "$why" ] && ! cmp -s "$t/free.msh" "$t/limited.msh" && why="meshes differ"
result "generous limit: byte-identical mesh" "$why"

# 4: a negative limit is a bad option (exit 2).
timeout 60 "$cli" mesh "$cube" -o "$t/n.msh" --time-limit -1 > /dev/null 2>&1; rc=$?
[ $rc -eq 2 ] && result "negative limit refused" "" || result "negative limit refused" "exit $rc"

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
