#!/bin/bash
# The CLI contract on the project's own models: --version, --help, info (text and JSON,
# part names, conformal preparation of an assembly), and the mesh command's report.
# usage: contract_test.sh CLI MODELS_DIR
cli=$1; models=$2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
pass=0; fail=0
ok() { pass=$((pass+1)); echo "ok $1"; }
bad() { fail=$((fail+1)); echo "FAIL $1"; }
py() { /usr/bin/python3 -c "$1"; }

"$cli" --version > "$t/v" 2>&1 && grep -q '^anisomesh [0-9]' "$t/v" && ok version || bad "version: $(cat "$t/v")"
"$cli" --help > "$t/h" 2>&1 && grep -q 'mesh' "$t/h" && grep -q 'info' "$t/h" && ok help || bad help
"$cli" mesh --help > "$t/h" 2>&1 && grep -q -- '--curvature-ratio' "$t/h" && ok mesh-help || bad mesh-help

# info, text form
if "$cli" info "$models/bracket.step" > "$t/i" 2> "$t/e" && grep -q 'BRACKET' "$t/i" && grep -q 'solids 1' "$t/i"; then ok info-text
else bad "info-text: $(cat "$t/i" "$t/e")"; fi

# info --json: the as-read keys, a bracket of one named solid with a positive volume
"$cli" info --json "$models/bracket.step" > "$t/j" 2> "$t/e"
if py "
import json; j = json.load(open('$t/j'))
assert all(k in j for k in ('solids','shells','faces','edges','vertices','volume','area')), j.keys()
assert j['solids'] == 1 and j['solid_list'][0]['name'] == 'BRACKET', j['solid_list']
assert abs(j['volume'] - 51133.894) < 0.1, j['volume']
assert j['prepared']['solids'] == 1
"; then ok info-json; else bad "info-json: $(cat "$t/e")"; fi

# the two-part assembly: names kept, and after preparation the interface is one shared face
"$cli" info --json "$models/assembly2.step" > "$t/a" 2> "$t/e"
if py "
import json; j = json.load(open('$t/a'))
names = sorted(s['name'] for s in j['solid_list'])
assert names == ['BASE', 'BLOCK'], names
p = j['prepared']
assert p['solids'] == 2 and p['shared_faces'] == 1, p
assert sorted(s['name'] for s in p['solid_list']) == ['BASE', 'BLOCK'], p['solid_list']
assert abs(p['volume'] - 20000) < 1e-3 * 20000, p['volume']
"; then ok assembly-conformal; else bad "assembly-conformal: $(cat "$t/e") $(head -c 600 "$t/a")"; fi
"$cli" info --json --no-fragment "$models/assembly2.step" > "$t/a" 2> "$t/e"
if py "
import json; p = json.load(open('$t/a'))['prepared']
assert p['shared_faces'] == 0, p
"; then ok no-fragment; else bad "no-fragment"; fi

# --progress: one line per update on a pipe, the faces phase with its predicted count
# (thesis 6.5), ended by a "done" line; without it a pipe gets no progress at all.
"$cli" --progress mesh "$models/plate.step" --dim 2 -o "$t/p.msh" > /dev/null 2> "$t/pe"
if grep -q '^progress: faces [0-9]*% .*triangles predicted' "$t/pe" && grep -q '^progress: faces done' "$t/pe" \
   && "$cli" mesh "$models/plate.step" --dim 2 -o "$t/q.msh" 2>&1 | { ! grep -q progress; }; then ok progress-lines
else bad "progress-lines: $(head -3 "$t/pe")"; fi

# mesh with the defaults: a volume mesh (the model has a solid), isotropic unless
# --anisotropy is given, and the report's contract.
"$cli" mesh "$models/bracket.step" -o "$t/out.msh" --report "$t/r.json" > "$t/so" 2> "$t/se"; rc=$?
if [ $rc -eq 0 ] && [ -s "$t/out.msh" ] && [ ! -s "$t/so" ] && py "
import json; r = json.load(open('$t/r.json'))
assert r['status'] == 'ok' and not r['failures'], r
for k in ('status','input','options','counts','times','quality','failures'): assert k in r, k
assert r['options']['dim'] == 3 and r['model']['solids'] == 1
assert r['options']['anisotropy'] == 1.0, r['options']
assert set(r['counts']) == {'nodes','triangles','quads','tetrahedra'}
assert r['counts']['tetrahedra'] > 1000, r['counts']
"; then ok mesh-report; else bad "mesh-report: exit $rc $(cat "$t/se")"; fi
"$cli" mesh "$models/bracket.step" -o "$t/an.msh" --anisotropy 3 --hmax-rel 0.2 --report "$t/a.json" > /dev/null 2>&1
if py "
import json; r = json.load(open('$t/a.json'))
assert r['options']['dim'] == 3 and r['options']['anisotropy'] == 3.0, r['options']
"; then ok anisotropy-given; else bad anisotropy-given; fi
echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
