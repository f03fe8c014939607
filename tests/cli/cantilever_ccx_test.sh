#!/bin/bash
# CalculiX end to end: models/cantilever.step (100 x 10 x 10) meshed with quadratic
# tetrahedra (--order 2 --hmax 5) to INP; a deck that *INCLUDEs it as written clamps FACE1
# (x = 0) and puts 100 N in -y on FACE2 (x = 100), spread over FACE2's nodes; steel
# (E 210000, nu 0.3). ccx must run without error and the mean y deflection of FACE2 must be
# within 3% of Timoshenko's 0.1920 (bending 0.1905 + shear 0.0015).
# usage: cantilever_ccx_test.sh CLI MODELS_DIR
cli=$1; models=$2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
"$cli" mesh "$models/cantilever.step" -o "$t/mesh.inp" --dim 3 --order 2 --hmax 5 -q > "$t/mesh.log" 2>&1 ||
  { echo "meshing failed: $(tail -1 "$t/mesh.log")"; exit 1; }
grep -q '^\*ELEMENT, TYPE=C3D10, ELSET=CANTILEVER$' "$t/mesh.inp" || { echo "no C3D10 block with ELSET=CANTILEVER"; exit 1; }
grep -qE 'TYPE=(S3|S6|S4|S8|CPS)' "$t/mesh.inp" && { echo "2D elements in a 3D deck"; exit 1; }
n2=$(/usr/bin/python3 - "$t/mesh.inp" <<'PY'
import sys
ids, on = [], False
for line in open(sys.argv[1]):
    if line.startswith("*"):
        on = line.strip().upper() == "*NSET, NSET=FACE2"; continue
    if on: ids += [x for x in line.replace(" ", "").strip().split(",") if x]
print(len(ids))
PY
)
[ "$n2" -gt 0 ] || { echo "FACE2 node set is empty"; exit 1; }
f=$(/usr/bin/python3 -c "print(repr(-100.0 / $n2))")
cat > "$t/job.inp" <<DECK
*INCLUDE, INPUT=mesh.inp
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=CANTILEVER, MATERIAL=STEEL
*STEP
*STATIC
*BOUNDARY
FACE1, 1, 3, 0.
*CLOAD
FACE2, 2, $f
*NODE PRINT, NSET=FACE2
U
*END STEP
DECK
(cd "$t" && timeout 600 ccx job > ccx.log 2>&1)
grep -q '\*ERROR' "$t/ccx.log" && { echo "ccx error: $(grep -m1 '\*ERROR' "$t/ccx.log")"; exit 1; }
[ -f "$t/job.dat" ] || { echo "ccx wrote no results"; exit 1; }
/usr/bin/python3 - "$t/job.dat" "$n2" <<'PY'
import sys
v = []
for line in open(sys.argv[1]):
    p = line.split()
    if len(p) == 4:
        try: v.append(float(p[2]))
        except ValueError: pass
n = int(sys.argv[2])
d = sum(v) / len(v) if v else float("nan")
err = abs(d + 0.1920) / 0.1920
print(f"cantilever: {len(v)} of {n} FACE2 nodes, mean tip deflection {d:.5f} vs Timoshenko -0.1920: error {err:.2%}")
sys.exit(0 if len(v) == n and err <= 0.03 else 1)
PY
