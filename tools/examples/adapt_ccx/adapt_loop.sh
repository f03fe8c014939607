#!/bin/bash
# Solve, adapt, solve again: a linear-elastic CalculiX analysis of a CAD model whose mesh is
# adapted to the von Mises stress of the previous solution (anisomesh adapt, issue 19).
#
#   adapt_loop.sh MODEL.step WORKDIR [ROUNDS] [TARGET_NODES]
#
# The model's face FIX (default FACE1, the INP writer's node set of face 1) is clamped, a
# total force FORCE (default -100, N) in direction DIR (default 2 = y) is spread over the
# nodes of face LOAD (default FACE2); steel (E 210000 MPa, nu 0.3); quadratic tets (C3D10).
# Round 0 is a uniform mesh of size H0 (default: the model's at --hmax 5); every round r
# writes WORKDIR/rR/{mesh.inp, job.frd, job.dat} and prints nodes and max von Mises.
# Needs anisomesh (ANISOMESH, default on PATH), ccx and /usr/bin/python3 (ccxlib.py beside it).
set -euo pipefail
model=$1; work=$2; rounds=${3:-2}; target=${4:-4000}
cli=${ANISOMESH:-anisomesh}
fix=${FIX:-FACE1}; load=${LOAD:-FACE2}; force=${FORCE:--100}; dir=${DIR:-2}; h0=${H0:-5}
mkdir -p "$work"

lib=$(cd "$(dirname "$0")" && pwd)/ccxlib.py

# the deck around mesh.inp; the load spread evenly over the loaded face's nodes
deck() {
  local d=$1
  local n
  n=$(/usr/bin/python3 "$lib" nset-count "$d/mesh.inp" "$load")
  [ "$n" -gt 0 ] || { echo "adapt_loop: node set $load is empty" >&2; exit 1; }
  local f
  f=$(/usr/bin/python3 -c "print(repr($force / $n))")
  cat > "$d/job.inp" <<DECK
*INCLUDE, INPUT=mesh.inp
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*STEP
*STATIC
*BOUNDARY
$fix, 1, 3, 0.
*CLOAD
$load, $dir, $f
*NODE FILE
U
*EL FILE
S
*END STEP
DECK
  (cd "$d" && ccx job > ccx.log 2>&1) || { echo "adapt_loop: ccx failed in $d" >&2; exit 1; }
  if grep -q '\*ERROR' "$d/ccx.log"; then echo "adapt_loop: $(grep -m1 '\*ERROR' "$d/ccx.log")" >&2; exit 1; fi
}

mises() { /usr/bin/python3 "$lib" max-mises "$1"; }
nodes() { /usr/bin/python3 "$lib" nodes "$1"; }

mkdir -p "$work/r0"
"$cli" mesh "$model" -o "$work/r0/mesh.inp" --dim 3 --order 2 --hmax "$h0" -q
deck "$work/r0"
echo "round 0: $(nodes "$work/r0/mesh.inp") nodes, max von Mises $(mises "$work/r0/job.frd")"
for r in $(seq 1 "$rounds"); do
  p=$work/r$((r - 1)); d=$work/r$r
  mkdir -p "$d"
  "$cli" adapt "$model" --from "$p/job.frd" --field STRESS -o "$d/mesh.inp" --order 2 --target-nodes "$target" \
    --report "$d/report.json" -q
  deck "$d"
  echo "round $r: $(nodes "$d/mesh.inp") nodes, max von Mises $(mises "$d/job.frd")"
done
