#!/bin/bash
# Element size a user can predict, and help written for people (issue 17; README "Element
# size"): the help has no parser internals; a misspelt option gets "did you mean"; conflicting
# size options exit 2 with a sentence; --hmax changes the bracket's tet count; the report's
# measured surface edges stay within the bounds; --size keeps curvature (--no-curvature not).
# usage: size_options_test.sh CLI MODELS_DIR
cli=$1; models=$2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
pass=0; fail=0
ok() { pass=$((pass+1)); echo "ok $1"; }
bad() { fail=$((fail+1)); echo "FAIL $1"; }
bracket="$models/bracket.step"

for cmd in "" info mesh sizing check; do
  "$cli" $cmd --help > "$t/help" 2>&1
  if grep -q -e '->' -e '{false}' -e ' OR {' -e 'FLOAT' -e 'POSITIVE' "$t/help"; then bad "help $cmd: $(grep -e '->' -e '{false}' -e ' OR {' -e FLOAT -e POSITIVE "$t/help" | head -1)"
  else ok "help-$cmd-plain"; fi
done
"$cli" mesh --help > "$t/help" 2>&1
for want in -v, -q, --progress --elements-per-circle --no-curvature "model units"; do
  grep -q -e "$want" "$t/help" && ok "mesh-help-has-$want" || bad "mesh --help lacks $want"
done

"$cli" mesh "$bracket" -o "$t/x.msh" --hmaxx 3 2> "$t/e"; rc=$?
[ $rc = 2 ] && grep -q "did you mean --hmax?" "$t/e" && ok did-you-mean || bad "--hmaxx: rc $rc: $(cat "$t/e")"
[ ! -e "$t/x.msh" ] || bad "--hmaxx wrote a mesh"

refuse() {  # name, then the options; exit 2, one line, no mesh
  local name=$1; shift
  "$cli" mesh "$bracket" -o "$t/c.msh" "$@" 2> "$t/e"; local rc=$?
  if [ $rc = 2 ] && [ "$(wc -l < "$t/e")" = 1 ] && [ ! -e "$t/c.msh" ]; then ok "refuse-$name"; else bad "$name: rc $rc: $(cat "$t/e")"; fi
}
refuse size-and-hmax --size 5 --hmax 2
refuse hmin-above-hmax --hmin 5 --hmax 2
refuse hmin-above-size --size 2 --hmin 5
refuse epc-and-ratio --elements-per-circle 12 --curvature-ratio 0.5
refuse no-curvature-and-epc --no-curvature --elements-per-circle 12
refuse hmax-and-rel --hmax 5 --hmax-rel 0.1
refuse epc-zero --elements-per-circle 0

tets() { /usr/bin/python3 -c "import json; print(json.load(open('$1'))['counts']['tetrahedra'])"; }
mesh() {  # report file, then options
  local r=$1; shift
  timeout 120 "$cli" mesh "$bracket" -o "$t/m.msh" -q --report "$r" "$@" || bad "mesh $*: exit $?"
}
# the elements per circle alone (the default chord bound refines the curved faces further,
# which leaves --hmax less to change: 15.4 k / 14.4 k tets)
mesh "$t/h5.json" --hmax 5 --chord-deviation-rel 0
mesh "$t/h20.json" --hmax 20 --chord-deviation-rel 0
mesh "$t/u5.json" --hmax 5 --no-curvature
mesh "$t/u20.json" --hmax 20 --no-curvature
mesh "$t/s5.json" --size 5
h5=$(tets "$t/h5.json"); h20=$(tets "$t/h20.json"); u5=$(tets "$t/u5.json"); u20=$(tets "$t/u20.json"); s5=$(tets "$t/s5.json")
echo "bracket tets: --hmax 5: $h5, --hmax 20: $h20; without curvature $u5, $u20; --size 5: $s5"
# with the curvature (12 per circle) the holes and fillets dominate; measured 7190 / 5989
[ "$h5" -gt $((h20 * 11 / 10)) ] && ok hmax-changes-count || bad "--hmax 5 ($h5) not 10 % above --hmax 20 ($h20)"
[ "$u5" -gt $((u20 * 2)) ] && ok hmax-uniform-2x || bad "--no-curvature: --hmax 5 ($u5) not 2x --hmax 20 ($u20)"
[ "$s5" -gt "$u5" ] && ok size-keeps-curvature || bad "--size 5 ($s5) not finer than --size 5 --no-curvature ($u5)"
if /usr/bin/python3 -c "
import json
for f, h in (('$t/h5.json', 5), ('$t/h20.json', 20)):
    s = json.load(open(f))['sizing']
    assert abs(s['hmax'] - h) < 1e-12 and s['elements_per_circle'] == 12, s
    e = s['surface_edge_length']
    # a boundary edge is accepted up to sqrt(2) x its size (the surface mesher's unit-length rule)
    assert e['edges'] > 0 and e['max'] <= 1.5 * h and e['min'] >= s['hmin'], (h, e)
"; then ok report-edge-lengths; else bad report-edge-lengths; fi

echo "$pass passed, $fail failed"
[ $fail = 0 ]
