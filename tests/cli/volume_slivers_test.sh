#!/bin/bash
# Surface slivers mended before the volume (VolumeMesher.h, SurfaceSlivers.h): U_Joint_2.stp
# has fillet tips where two CAD edges run 1e-6 apart; the strip between them is meshed with
# caps and node pairs a few micrometres apart, which force flat tetrahedra (before the
# mending: smallest dihedral angle 0.01 degrees, and boundary edges no interior point
# recovered, split as the last resort). The run must end ok with caps flipped and nodes
# merged in the report, a valid closed tet mesh (anisomesh check), the CAD volume and a
# smallest dihedral angle >= 2 degrees (the referee, shared/tools/meshq.py).
# usage: volume_slivers_test.sh CLI SHARED_MODELS_DIR
cli=$1; models=$2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
"$cli" mesh "$models/U_Joint_2.stp" -o "$t/u.msh" --report "$t/r.json" --hmax-rel 0.02 --curvature-ratio 0.26 \
  --anisotropy 1 > /dev/null 2> "$t/e"; rc=$?
[ $rc -eq 0 ] || { echo "FAIL exit $rc: $(cat "$t/e")"; exit 1; }
"$cli" check "$t/u.msh" > "$t/c" 2>&1 || { echo "FAIL check: $(tail -5 "$t/c")"; exit 1; }
/usr/bin/python3 - "$t/r.json" "$models/MANIFEST.json" "$t/u.msh" "$models/../tools" <<'PY'
import json, sys
sys.path.insert(0, sys.argv[4])
import meshq
r = json.load(open(sys.argv[1]))
m = [x for x in json.load(open(sys.argv[2])) if x["file"] == "U_Joint_2.stp"][0]
q = meshq.stats(sys.argv[3])
rec = r["recovery"]
print("status", r["status"], "tets", r["counts"]["tetrahedra"], "caps flipped", rec["surface_caps_flipped"],
      "nodes merged", rec["surface_nodes_merged"], "boundary splits", rec["steiner_points_boundary"],
      "dihedral_min", q["dihedral_min"])
assert r["status"] == "ok", r["failures"]
assert rec["surface_caps_flipped"] > 0 and rec["surface_nodes_merged"] > 0, rec
assert abs(r["volume"] - m["volume"]) <= 0.01 * m["volume"], (r["volume"], m["volume"])
assert q["inverted"] == 0 and q["dihedral_min"] >= 2.0, q
PY
