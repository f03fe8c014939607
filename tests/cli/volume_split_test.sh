#!/bin/bash
# The last resort of boundary recovery (VolumeMesher.h, SplitSurfaceEdges.h): U_Joint_2.stp
# has boundary edges that no interior point recovers (nearly flat surface triangles); they
# are split in the surface mesh and the solid is meshed again. The run must end ok, with
# boundary Steiner points in the report, a valid closed tet mesh (anisomesh check) and the
# CAD volume.
# usage: volume_split_test.sh CLI SHARED_MODELS_DIR
cli=$1; models=$2
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
"$cli" mesh "$models/U_Joint_2.stp" -o "$t/u.msh" --report "$t/r.json" --hmax-rel 0.02 --curvature-ratio 0.26 \
  --anisotropy 1 > /dev/null 2> "$t/e"; rc=$?
[ $rc -eq 0 ] || { echo "FAIL exit $rc: $(cat "$t/e")"; exit 1; }
"$cli" check "$t/u.msh" > "$t/c" 2>&1 || { echo "FAIL check: $(tail -5 "$t/c")"; exit 1; }
/usr/bin/python3 - "$t/r.json" "$models/MANIFEST.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
m = [x for x in json.load(open(sys.argv[2])) if x["file"] == "U_Joint_2.stp"][0]
rec = r["recovery"]
print("status", r["status"], "tets", r["counts"]["tetrahedra"], "boundary splits", rec["steiner_points_boundary"],
      "rounds", rec["split_rounds"])
assert r["status"] == "ok", r["failures"]
assert rec["steiner_points_boundary"] > 0 and rec["split_rounds"] > 0, rec
assert abs(r["volume"] - m["volume"]) <= 0.01 * m["volume"], (r["volume"], m["volume"])
PY
