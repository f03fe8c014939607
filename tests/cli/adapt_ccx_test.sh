#!/bin/bash
# CalculiX round trip of anisomesh adapt (issue 19): tools/examples/adapt_ccx/adapt_loop.sh on
# models/cantilever.step, one round to 3000 nodes (C3D10): ccx solves the uniform mesh, adapt
# reads its .frd (von Mises of STRESS), ccx solves the adapted mesh. Checks: the adapted
# deck has 3000 nodes within 30 %; the field range the report gives is the von Mises range
# computed here from the .frd text; an .frd cut before its results exits 2 naming the file.
# usage: adapt_ccx_test.sh CLI MODELS_DIR SOURCE_DIR
cli=$1; models=$2; src=$3
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
ANISOMESH=$cli timeout 600 bash "$src/tools/examples/adapt_ccx/adapt_loop.sh" "$models/cantilever.step" "$t/loop" 1 3000 \
  > "$t/loop.log" 2>&1 || { echo "adapt_loop failed: $(tail -3 "$t/loop.log")"; exit 1; }
cat "$t/loop.log"
/usr/bin/python3 - "$t/loop" "$src/tools/examples/adapt_ccx" <<'PY' || exit 1
import json, math, sys
d = sys.argv[1]
sys.path.insert(0, sys.argv[2])
from ccxlib import frd_mises
vm = list(frd_mises(d + "/r0/job.frd").values())
r = json.load(open(d + "/r1/report.json"))
ad = r.get("extra", r)["adapt"]
n = r["counts"]["nodes"]
ok_range = math.isclose(ad["field_min"], min(vm), rel_tol=1e-9) and math.isclose(ad["field_max"], max(vm), rel_tol=1e-9)
ok_count = 2100 <= n <= 3900
print(f"von Mises range {ad['field_min']:.5g}..{ad['field_max']:.5g} (here {min(vm):.5g}..{max(vm):.5g}); {n} nodes for 3000")
sys.exit(0 if ok_range and ok_count else 1)
PY
# an .frd without results: the mesh blocks only
sed '/1PSTEP/,$d' "$t/loop/r0/job.frd" > "$t/nores.frd"
"$cli" adapt "$models/cantilever.step" --from "$t/nores.frd" --field STRESS -o "$t/x.inp" -q 2> "$t/err"; rc=$?
[ $rc -eq 2 ] && grep -q "nores.frd: no field" "$t/err" && [ ! -e "$t/x.inp" ] ||
  { echo "FRD without results: exit $rc: $(cat "$t/err")"; exit 1; }
echo "FRD without results: exit 2: $(cat "$t/err")"
