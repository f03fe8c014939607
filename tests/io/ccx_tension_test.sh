#!/bin/bash
# CalculiX runs our INP as written: a 10 x 3 x 2 box of Kuhn tetrahedra (C3D4, then C3D10)
# written by io_write_fixtures, symmetry supports on FACE1 (x = 0), FACE3 (y = 0) and
# FACE5 (z = 0) through the node sets, a tension of 100 MPa on FACE2 (x = 10) through the
# element-face surface S_FACE2 (*DSLOAD, P = -100). The solution is uniform: every
# integration point must give sxx = 100 and the other stresses 0, and FACE2 must move by
# 100 * 10 / 210000 in x. A wrong Abaqus face number (S1..S4) would load interior faces;
# a wrong C3D10 node order would distort the elements: either breaks the exact answer.
# Then the surface meshes' shell decks (S3/S4 and S6/S8, ELSET EALL, NSET FACE<n>) run too.
# usage: ccx_tension_test.sh IO_WRITE_FIXTURES
fixtures=$1
t=$(mktemp -d); trap 'rm -rf $t' EXIT
"$fixtures" $t > $t/fixtures.log 2>&1 || { echo "io_write_fixtures failed: $(tail -1 $t/fixtures.log)"; exit 1; }
fail=0
for mesh in tet4 tet10; do
  cat > $t/$mesh-job.inp <<DECK
*INCLUDE, INPUT=$mesh.inp
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*STEP
*STATIC
*BOUNDARY
FACE1, 1, 1, 0.
FACE3, 2, 2, 0.
FACE5, 3, 3, 0.
*DSLOAD
S_FACE2, P, -100.
*EL PRINT, ELSET=EALL
S
*NODE PRINT, NSET=FACE2
U
*END STEP
DECK
  (cd $t && timeout 300 ccx $mesh-job > $mesh-ccx.log 2>&1)
  if grep -q '\*ERROR' $t/$mesh-ccx.log || [ ! -f $t/$mesh-job.dat ]; then
    echo "$mesh: ccx failed: $(grep -m1 '\*ERROR' $t/$mesh-ccx.log)"; fail=1; continue
  fi
  /usr/bin/python3 - $t/$mesh-job.dat $mesh <<'PY' || fail=1
import sys
stress, disp, section = [], [], None
for line in open(sys.argv[1]):
    if "stresses" in line: section = "s"; continue
    if "displacements" in line: section = "u"; continue
    p = line.split()
    try: v = [float(x) for x in p]
    except ValueError: continue
    if section == "s" and len(v) == 8: stress.append(v[2:])
    if section == "u" and len(v) == 4: disp.append(v[1:])
ok = bool(stress) and bool(disp)
err_s = max((max(abs(s[0] - 100.0), *map(abs, s[1:])) for s in stress), default=float("inf"))
err_u = max((abs(u[0] - 100.0 * 10 / 210000.0) for u in disp), default=float("inf"))
ok = ok and err_s < 1e-6 * 100 and err_u < 1e-6 * 100.0 * 10 / 210000.0
print(f"{sys.argv[2]}: {len(stress)} integration points, max stress error {err_s:.2e} MPa; "
      f"{len(disp)} FACE2 nodes, max ux error {err_u:.2e}: {'ok' if ok else 'WRONG'}")
sys.exit(0 if ok else 1)
PY
done
# Surface meshes: the shell decks (S3/S4, S6/S8) run as written; FACE2 pulled in +x moves in +x.
for mesh in quad4 quad8; do
  cat > $t/$mesh-job.inp <<DECK
*INCLUDE, INPUT=$mesh.inp
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SHELL SECTION, ELSET=EALL, MATERIAL=STEEL
0.1
*STEP
*STATIC
*BOUNDARY
FACE1, 1, 6, 0.
*CLOAD
FACE2, 1, 1.
*NODE PRINT, NSET=FACE2
U
*END STEP
DECK
  (cd $t && timeout 300 ccx $mesh-job > $mesh-ccx.log 2>&1)
  if grep -q '\*ERROR' $t/$mesh-ccx.log || [ ! -f $t/$mesh-job.dat ]; then
    echo "$mesh: ccx failed: $(grep -m1 '\*ERROR' $t/$mesh-ccx.log)"; fail=1; continue
  fi
  /usr/bin/python3 - $t/$mesh-job.dat $mesh <<'PY' || fail=1
import sys
u = [float(l.split()[1]) for l in open(sys.argv[1]) if len(l.split()) == 4 and l.split()[0].isdigit()]
ok = bool(u) and min(u) > 0
print(f"{sys.argv[2]} shells: {len(u)} FACE2 nodes, ux {min(u, default=0):.3g}..{max(u, default=0):.3g}: {'ok' if ok else 'WRONG'}")
sys.exit(0 if ok else 1)
PY
done
exit $fail
