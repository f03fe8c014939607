#!/usr/bin/env bash
# Sizing that cannot explode (issue 20): the passage model (a B-spline patch with a collapsed
# control row and noise) meshes to a bounded count, and the element budget (--max-elements)
# coarsens or refuses before meshing.
# Usage: budget_test.sh ANISOMESH MODELS_DIR
set -u
bin=$1; models=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
census=(--dim 2 --hmax-rel 0.02 --curvature-ratio 0.26 --anisotropy 1)
json() { /usr/bin/python3 -c "import json,sys; r=json.load(open('$1')); print(eval(sys.argv[1]))" "$2"; }

# 1. passage.step at the census options: before the robust curvature its control spaces
#    alone grew past 1 M vertices (h_min at the collapsed row, > 120 s); now ~53 k triangles.
timeout 120 "$bin" mesh "$models/passage.step" -o "$tmp/p.msh" "${census[@]}" --report "$tmp/p.json" || fail "passage: exit $?"
[ "$(json "$tmp/p.json" "r['status']")" = ok ] || fail "passage: status not ok"
tri=$(json "$tmp/p.json" "r['counts']['triangles']")
[ "$tri" -lt 80000 ] || fail "passage: $tri triangles (bound 80000)"
[ "$(json "$tmp/p.json" "r['surface']['open_edges']")" = 0 ] || fail "passage: open edges"
pred=$(json "$tmp/p.json" "int(r['budget']['predicted'])")
/usr/bin/python3 -c "import sys; p,t=$pred,$tri; sys.exit(0 if 0.7*t < p < 1.3*t else 1)" || fail "passage: predicted $pred for $tri triangles"
echo "passage: $tri triangles (predicted $pred)"

# 2. a budget that even h_max cannot meet: exit 2, the prediction and the budget in the
#    message, no mesh written.
fine=(--dim 2 --hmax-rel 0.1 --curvature-ratio 0.05)
"$bin" mesh "$models/bracket.step" -o "$tmp/b.msh" "${fine[@]}" --max-elements 100 2> "$tmp/err"
rc=$?
[ $rc = 2 ] || fail "max-elements 100: exit $rc, expected 2"
grep -q "asks for about [0-9]* elements" "$tmp/err" || fail "no prediction in: $(cat "$tmp/err")"
grep -q "budget of 100 " "$tmp/err" || fail "no budget in: $(cat "$tmp/err")"
[ ! -e "$tmp/b.msh" ] || fail "a mesh was written"

# 3. over the budget but coarsenable: exit 0, one warning naming the faces, the report's
#    budget block, fewer triangles than asked.
"$bin" mesh "$models/bracket.step" -o "$tmp/c.msh" "${fine[@]}" --report "$tmp/full.json" || fail "bracket: exit $?"
full=$(json "$tmp/full.json" "r['counts']['triangles']")
"$bin" mesh "$models/bracket.step" -o "$tmp/c.msh" "${fine[@]}" --max-elements 1500 --report "$tmp/c.json" 2> "$tmp/err" || fail "budget 1500: exit $?"
[ "$(grep -c "warning: .*over the budget of 1500 (--max-elements): faces [0-9]" "$tmp/err")" = 1 ] || fail "no warning: $(cat "$tmp/err")"
faces=$(json "$tmp/c.json" "len(r['budget']['coarsened_faces'])")
[ "$faces" -gt 0 ] || fail "no coarsened faces in the report"
tri=$(json "$tmp/c.json" "r['counts']['triangles']")
[ "$tri" -lt 2000 ] || fail "budget 1500: $tri triangles (asked $full)"
[ "$(json "$tmp/c.json" "r['surface']['open_edges']")" = 0 ] || fail "budget 1500: open edges"
echo "bracket: $full triangles asked, $tri within the budget of 1500 ($faces faces coarsened)"
# 4. dim 3: the tets count too (the census options ask for ~8 k triangles and ~71 k tets).
"$bin" mesh "$models/bracket.step" -o "$tmp/v.msh" --hmax-rel 0.02 --curvature-ratio 0.26 --max-elements 20000 2> "$tmp/err"
rc=$?
[ $rc = 2 ] || fail "dim 3, max-elements 20000: exit $rc, expected 2"
grep -q "triangles, [0-9]* tets)" "$tmp/err" || fail "no tets in: $(cat "$tmp/err")"
[ ! -e "$tmp/v.msh" ] || fail "a volume mesh was written"
echo PASS
