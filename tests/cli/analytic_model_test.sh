#!/bin/bash
# Analytic .json models: accepted (info, and mesh up to the meshing step) and every
# malformed one refused with exit 2 and one line naming the file and the field.
# usage: analytic_model_test.sh CLI SHARED_BENCH_DIR
cli=$1; bench=$2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
pass=0; fail=0
ok() { pass=$((pass+1)); echo "ok $1"; }
bad() { fail=$((fail+1)); echo "FAIL $1"; }
py() { /usr/bin/python3 -c "$1"; }

"$cli" info --json "$bench/AN1.json" > "$t/a" 2> "$t/e"
if py "
import json; j = json.load(open('$t/a'))
assert j['faces'] == 1 and j['edges'] == 4 and j['vertices'] == 4, j
assert j['sizing']['angle'] == 'pi/6', j
b = j['bbox']; assert b['min'][:2] == [0, 0] and b['max'][:2] == [2, 1], b
"; then ok an1-info; else bad "an1-info: $(cat "$t/e")"; fi

cat > "$t/holes.json" <<'J'
{"name": "H", "surface": {"type": "expression", "x": "u", "y": "v", "z": "1.5*exp(-0.001*(u^2+v^2))*sin(2*u)*cos(0.2*v)"},
 "domain": {"u": [-6, 6], "v": [-6, 6]},
 "holes": [{"type": "circle", "center": [2, 2], "radius": 1},
           {"type": "polygon", "points": [[-4, -4], [-2, -4], [-3, -2]]}]}
J
"$cli" info --json "$t/holes.json" > "$t/a" 2> "$t/e"
if py "
import json; j = json.load(open('$t/a'))
assert j['holes'] == 2 and j['edges'] == 4 + 1 + 3, j
assert j['bbox']['max'][2] > 1.0, j['bbox']   # the patch bulges above its boundary
"; then ok holes-info; else bad "holes-info: $(cat "$t/e") $(cat "$t/a")"; fi

# the analytic patch with holes meshes: report ok, triangles on the surface, none in the holes
"$cli" mesh "$t/holes.json" -o "$t/out.msh" --report "$t/r.json" --hmax 0.5 2> "$t/e"; rc=$?
if [ $rc -eq 0 ] && py "
import json, meshio, numpy as np
r = json.load(open('$t/r.json')); assert r['status'] == 'ok' and r['options']['dim'] == 2, r['status']
m = meshio.read('$t/out.msh'); P = m.points
T = np.vstack([c.data for c in m.cells if c.type == 'triangle'])
assert r['counts']['triangles'] == len(T)
c = P[T].mean(axis=1)
assert not np.any(np.hypot(c[:, 0] - 2, c[:, 1] - 2) < 0.95), 'triangle inside the circular hole'
z = 1.5*np.exp(-0.001*(P[:,0]**2+P[:,1]**2))*np.sin(2*P[:,0])*np.cos(0.2*P[:,1])
assert np.abs(P[:, 2] - z).max() < 1e-9, 'nodes off the surface'
"; then ok holes-mesh; else bad "holes-mesh: exit $rc $(cat "$t/e")"; fi

refuse() { # name word json [extra options]
  local name=$1 word=$2
  printf '%s' "$3" > "$t/m.json"; shift 3
  rm -f "$t/out.msh"
  "$cli" mesh "$t/m.json" -o "$t/out.msh" "$@" > /dev/null 2> "$t/e"; local rc=$?
  if [ $rc -eq 2 ] && [ "$(wc -l < "$t/e")" -eq 1 ] && grep -q "m.json" "$t/e" && grep -qi -- "$word" "$t/e" && [ ! -e "$t/out.msh" ]; then
    ok "$name: $(cat "$t/e")"; else bad "$name: exit $rc $(cat "$t/e")"; fi
}
D='"domain": {"u": [0, 2], "v": [0, 1]}'
refuse not-json "json" '{"surface": '
refuse no-domain "domain" '{"surface": {"type": "plane"}}'
refuse empty-domain "domain" '{"surface": {"type": "plane"}, "domain": {"u": [1, 1], "v": [0, 1]}}'
refuse bad-surface-type "surface.type" '{"surface": {"type": "nurbs"}, '"$D"'}'
refuse bad-expression "surface" '{"surface": {"type": "expression", "x": "u", "y": "v", "z": "sin(u"}, '"$D"'}'
refuse hole-outside "holes\[0\]" '{"surface": {"type": "plane"}, '"$D"', "holes": [{"type": "circle", "center": [1.9, 0.5], "radius": 0.2}]}'
refuse holes-overlap "overlaps" '{"surface": {"type": "plane"}, '"$D"', "holes": [{"type": "circle", "center": [0.5, 0.5], "radius": 0.2}, {"type": "polygon", "points": [[0.6, 0.4], [0.9, 0.4], [0.9, 0.6]]}]}'
refuse self-crossing "crosses itself" '{"surface": {"type": "plane"}, '"$D"', "holes": [{"type": "polygon", "points": [[0.2, 0.2], [0.6, 0.6], [0.6, 0.2], [0.2, 0.6]]}]}'
refuse bad-sizing "sizing.h2" '{"surface": {"type": "plane"}, '"$D"', "sizing": {"h1": "0.01", "h2": "0.0101 - 0.5*u"}}'
refuse sizing-syntax "sizing.h1" '{"surface": {"type": "plane"}, '"$D"', "sizing": {"h1": "0.01*"}}'
refuse dim3 "3D" '{"surface": {"type": "plane"}, '"$D"'}' --dim 3
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
