#!/bin/bash
# The FreeCAD macro, headless (issue 8): a 40x20x10 box with a 4 mm radius through-hole
# (Part::Cut) inside a FEM analysis is meshed through tools/freecad/AnisoMesh.FCMacro with
# --hmax 3, saved and reopened: one FemMeshObject in the analysis, > 100 tetrahedra, a node
# group per CAD face (Face1..Face7) and a Solid1 group, every node inside the shape's
# bounding box. A failing CLI run exits non-zero and creates no FemMeshObject.
# usage: freecad_macro_test.sh CLI PROJECT_DIR
cli=$1; proj=$2
macro=$proj/tools/freecad/AnisoMesh.FCMacro
command -v freecadcmd > /dev/null || { echo "freecadcmd not installed (package freecad-python3)"; exit 1; }
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
export HOME=$t   # freecadcmd writes its settings under $HOME
pass=0; fail=0
ok() { pass=$((pass+1)); echo "ok $1"; }
bad() { fail=$((fail+1)); echo "FAIL $1"; }

cat > "$t/make.py" <<'PY'
import sys, FreeCAD, Part, ObjectsFem
doc = FreeCAD.newDocument("T")
b = doc.addObject("Part::Box", "Box"); b.Length = 40; b.Width = 20; b.Height = 10
c = doc.addObject("Part::Cylinder", "Hole"); c.Radius = 4; c.Height = 10
c.Placement.Base = FreeCAD.Vector(20, 10, 0)
cut = doc.addObject("Part::Cut", "Plate"); cut.Base = b; cut.Tool = c
ObjectsFem.makeAnalysis(doc, "Analysis")
doc.recompute()
doc.saveAs(sys.argv[-1])
sys.exit(0)
PY
(cd "$t" && freecadcmd make.py "$t/in.FCStd" > make.log 2>&1)
[ -f "$t/in.FCStd" ] || { echo "FAIL could not build the test document: $(tail -3 "$t/make.log")"; exit 1; }

# 1. a successful run
(cd "$t" && ANISOMESH="$cli" ANISOMESH_DOCUMENT="$t/in.FCStd" ANISOMESH_OBJECTS=Plate ANISOMESH_OPTIONS="--hmax 3" \
   ANISOMESH_SAVE="$t/out.FCStd" timeout 600 freecadcmd "$macro" > macro.log 2>&1); rc=$?
if [ $rc -eq 0 ] && [ -f "$t/out.FCStd" ]; then ok macro-runs; else bad "macro-runs: exit $rc: $(grep anisomesh "$t/macro.log" | tail -2)"; fi

# (not "inspect.py": freecadcmd would take the standard module of that name)
cat > "$t/fc_inspect.py" <<PY
import sys, json, traceback, FreeCAD
try:
  doc = FreeCAD.openDocument("$t/out.FCStd")
  meshes = [o for o in doc.Objects if o.TypeId.startswith("Fem::FemMeshObject")]
  r = {"meshes": len(meshes)}
  if meshes:
      m = meshes[0].FemMesh
      bb = doc.getObject("Plate").Shape.BoundBox
      eps = 1e-6 * bb.DiagonalLength
      inside = all(bb.XMin - eps <= p.x <= bb.XMax + eps and bb.YMin - eps <= p.y <= bb.YMax + eps and
                   bb.ZMin - eps <= p.z <= bb.ZMax + eps for p in m.Nodes.values())
      names = sorted(m.getGroupName(g) for g in m.Groups)
      an = doc.getObject("Analysis")
      r.update(tets=m.TetraCount, nodes=m.NodeCount, groups=names, inside=inside,
               in_analysis=meshes[0] in an.Group,
               face_nodes={n: len(m.getGroupElements(g)) for g in m.Groups for n in [m.getGroupName(g)]})
  json.dump(r, open("$t/inspect.json", "w"))
except Exception:
  json.dump({"error": traceback.format_exc()}, open("$t/inspect.json", "w"))
sys.exit(0)
PY
(cd "$t" && freecadcmd fc_inspect.py > fc_inspect.log 2>&1)
if /usr/bin/python3 - "$t/inspect.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(json.dumps({k: v for k, v in r.items() if k != "face_nodes"}))
assert "error" not in r, r["error"]
assert r["meshes"] == 1, r
assert r["tets"] > 100, r
faces = [f"Face{i}" for i in range(1, 8)]
assert all(f in r["groups"] for f in faces), r["groups"]
assert "Face8" not in r["groups"], r["groups"]
assert "Solid1" in r["groups"], r["groups"]
assert all(r["face_nodes"][f] >= 3 for f in faces), r["face_nodes"]
assert r["inside"], "a node outside the shape's bounding box"
assert r["in_analysis"], "the mesh is not in the analysis"
PY
then ok reopened-mesh; else bad reopened-mesh; fi

# 2. a failing run (absurd option: the CLI exits 2) creates nothing and exits non-zero
(cd "$t" && ANISOMESH="$cli" ANISOMESH_DOCUMENT="$t/in.FCStd" ANISOMESH_OBJECTS=Plate ANISOMESH_OPTIONS="--hmax -3" \
   ANISOMESH_SAVE="$t/fail.FCStd" timeout 300 freecadcmd "$macro" > fail.log 2>&1); rc=$?
if [ $rc -ne 0 ] && [ ! -e "$t/fail.FCStd" ] && grep -q "anisomesh: .*hmax" "$t/fail.log"; then ok failure-creates-nothing
else bad "failure-creates-nothing: exit $rc: $(grep anisomesh "$t/fail.log" | tail -2)"; fi

# 3. an unknown object name: a clear message, non-zero exit
(cd "$t" && ANISOMESH="$cli" ANISOMESH_DOCUMENT="$t/in.FCStd" ANISOMESH_OBJECTS=NoSuchThing \
   timeout 300 freecadcmd "$macro" > missing.log 2>&1); rc=$?
if [ $rc -ne 0 ] && grep -q "no object named NoSuchThing" "$t/missing.log"; then ok unknown-object
else bad "unknown-object: exit $rc"; fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
