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
# Needs anisomesh (ANISOMESH, default on PATH), ccx and /usr/bin/python3.
set -euo pipefail
model=$1; work=$2; rounds=${3:-2}; target=${4:-4000}
cli=${ANISOMESH:-anisomesh}
fix=${FIX:-FACE1}; load=${LOAD:-FACE2}; force=${FORCE:--100}; dir=${DIR:-2}; h0=${H0:-5}
mkdir -p "$work"

# the deck around mesh.inp; the load spread evenly over the loaded face's nodes
deck() {
  local d=$1
  local n
  n=$(/usr/bin/python3 - "$d/mesh.inp" "$load" <<'PY'
import sys
ids, on = [], False
for line in open(sys.argv[1]):
    if line.startswith("*"):
        on = line.strip().upper() == "*NSET, NSET=" + sys.argv[2].upper(); continue
    if on: ids += [x for x in line.replace(" ", "").strip().split(",") if x]
print(len(ids))
PY
)
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

# max von Mises over the nodes of job.frd
mises() {
  /usr/bin/python3 - "$1" <<'PY'
import sys, math
lines = open(sys.argv[1]).read().splitlines()
start = max(i for i, l in enumerate(lines) if l.startswith(" -4  STRESS"))
best = 0.0
for l in lines[start + 1:]:
    if l.startswith(" -3"): break
    if not l.startswith(" -1"): continue
    s = [float(l[13 + 12 * c: 25 + 12 * c]) for c in range(6)]
    a, b, c = s[0] - s[1], s[1] - s[2], s[2] - s[0]
    best = max(best, math.sqrt(0.5 * (a * a + b * b + c * c) + 3 * (s[3] ** 2 + s[4] ** 2 + s[5] ** 2)))
print(f"{best:.4f}")
PY
}

nodes() { grep -c '^ *[0-9]' <(sed -n '/^\*NODE/,/^\*/p' "$1") || true; }

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
