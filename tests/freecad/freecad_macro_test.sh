#!/bin/bash
# The FreeCAD macro, headless (issues 8, 17), through freecadcmd:
#  1. a 40x20x10 plate with a 4 mm radius through-hole (Part::Cut `Plate`) in a FEM analysis,
#     meshed through tools/freecad/AnisoMesh.FCMacro with --hmax 3, saved and reopened: one
#     FemMeshObject in the analysis, > 100 tetrahedra, its `Part` link is Plate, groups
#     Plate and Plate_Face1..7 whose nodes are exactly the nodes FreeCAD's getNodesByFace finds
#     on Face<n> of Plate, every node inside the plate's bounding box; the summary line printed;
#  2. several objects: boxes Box and Box001 touching (one interface), a cylinder Fix_pin
#     through Box001 (overlap): groups named after each object and its own face numbers (again
#     equal to getNodesByFace on every face of every object), the Part link a Part::Compound
#     of the three, the CLI's overlap warning printed with the objects' names (not SOLID<k>),
#     and a warning that group Fix_pin_Face1 starts with the name of the analysis' constraint
#     Fix (FreeCAD's writers would take it for Fix's node set);
#     a quadratic surface mesh of a Part::Plane `Sheet`: groups Sheet (its shells), Sheet_Face1;
#  3. FreeCAD's CalculiX workflow (freecad_ccx.py): no "Not all methods do work" or any other
#     warning, ccx exits 0, tip displacement of the box in tension within 3% of F L / (E A);
#  4. the dialog's defaults: read from `anisomesh mesh --help`, an untouched dialog sends no
#     option (the CLI's own defaults), a changed value is sent;
#  5. a failing CLI run exits non-zero and creates nothing; an unknown object name is said.
# usage: freecad_macro_test.sh CLI PROJECT_DIR
cli=$1; proj=$2
macro=$proj/tools/freecad/AnisoMesh.FCMacro
command -v freecadcmd > /dev/null || { echo "freecadcmd not installed (package freecad-python3)"; exit 1; }
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
export HOME=$t   # freecadcmd writes its settings under $HOME
export ANISOMESH="$cli" ANISOMESH_MACRO_DIR="$proj/tools/freecad"
pass=0; fail=0
ok() { pass=$((pass+1)); echo "ok $1"; }
bad() { fail=$((fail+1)); echo "FAIL $1"; }

cat > "$t/make.py" <<'PY'
import sys, FreeCAD, Part, ObjectsFem
doc = FreeCAD.newDocument("T")
b = doc.addObject("Part::Box", "PlateBox"); b.Length = 40; b.Width = 20; b.Height = 10
c = doc.addObject("Part::Cylinder", "Hole"); c.Radius = 4; c.Height = 10
c.Placement.Base = FreeCAD.Vector(20, 10, 0)
cut = doc.addObject("Part::Cut", "Plate"); cut.Base = b; cut.Tool = c
for name, x in (("Box", 0), ("Box001", 10)):
    o = doc.addObject("Part::Box", name); o.Length = o.Width = o.Height = 10
    o.Placement.Base = FreeCAD.Vector(x, 100, 0)
pin = doc.addObject("Part::Cylinder", "Fix_pin"); pin.Radius = 2; pin.Height = 14
pin.Placement.Base = FreeCAD.Vector(15, 105, -2)
sheet = doc.addObject("Part::Plane", "Sheet"); sheet.Length = sheet.Width = 30
sheet.Placement.Base = FreeCAD.Vector(0, 200, 0)
analysis = ObjectsFem.makeAnalysis(doc, "Analysis")
fix = ObjectsFem.makeConstraintFixed(doc, "Fix"); fix.References = [(doc.Box, "Face1")]
analysis.addObject(fix)
doc.recompute()
doc.saveAs(sys.argv[-1])
sys.exit(0)
PY
(cd "$t" && freecadcmd make.py "$t/in.FCStd" > make.log 2>&1)
[ -f "$t/in.FCStd" ] || { echo "FAIL could not build the test document: $(tail -3 "$t/make.log")"; exit 1; }

# 1, 2. successful runs (stderr only: freecadcmd's own output goes to stdout)
run() {  # run NAME OBJECTS OPTIONS
  (cd "$t" && ANISOMESH_DOCUMENT="$t/in.FCStd" ANISOMESH_OBJECTS=$2 ANISOMESH_OPTIONS="$3" \
     ANISOMESH_SAVE="$t/$1.FCStd" timeout 300 freecadcmd "$macro" > "$1.out" 2> "$1.err"); rc=$?
  if [ $rc -eq 0 ] && [ -f "$t/$1.FCStd" ]; then ok "$1-runs"; else bad "$1-runs: exit $rc: $(tail -2 "$t/$1.err")"; fi
}
run plate Plate "--hmax 3"
run several Box,Box001,Fix_pin ""
run sheet Sheet "--order 2"
if grep -q "^anisomesh: AnisoMesh of Plate: [0-9]* nodes, [0-9]* tetrahedra, .*mean ratio min 0\.[0-9]* mean 0\.[0-9]*, .* groups, .* 0 warnings$" "$t/plate.err"
then ok summary-line; else bad "summary-line: $(cat "$t/plate.err")"; fi
if grep -q "^anisomesh: warning: .*'Box001' and .*'Fix_pin' share a volume" "$t/several.err" && ! grep -q SOLID "$t/several.err"
then ok overlap-warning-names; else bad "overlap-warning-names: $(cat "$t/several.err")"; fi
if grep -q "^anisomesh: warning: group Fix_pin_Face1 starts with the name of Fix: " "$t/several.err"
then ok group-prefix-clash-warned; else bad "group-prefix-clash-warned: $(cat "$t/several.err")"; fi

# (not "inspect.py": freecadcmd would take the standard module of that name)
cat > "$t/fc_inspect.py" <<PY
import sys, json, traceback, FreeCAD
def inspect(path, names):
    doc = FreeCAD.openDocument(path)
    meshes = [o for o in doc.Objects if o.TypeId.startswith("Fem::FemMeshObject")]
    r = {"meshes": len(meshes)}
    if not meshes:
        return r
    o = meshes[0]; m = o.FemMesh
    groups = {m.getGroupName(g): g for g in m.Groups}
    part = getattr(o, "Part", None)
    r.update(tets=m.VolumeCount, groups=sorted(groups), in_analysis=o in doc.getObject("Analysis").Group,
             part=part.Name if part else None, part_type=part.TypeId if part else None,
             part_links=[l.Name for l in getattr(part, "Links", [])], options=o.AnisoMeshOptions)
    r["faces_equal"], r["volumes"] = {}, {}
    for n in names:
        shape = doc.getObject(n).Shape
        for k, face in enumerate(shape.Faces, start=1):
            g = groups.get(f"{n}_Face{k}")
            r["faces_equal"][f"{n}_Face{k}"] = g is not None and sorted(m.getGroupElements(g)) == sorted(m.getNodesByFace(face))
        r["volumes"][n] = len(m.getGroupElements(groups[n])) if n in groups else 0
        bb = shape.BoundBox; eps = 1e-6 * bb.DiagonalLength
    if names == ["Plate"]:
        r["inside"] = all(bb.XMin - eps <= p.x <= bb.XMax + eps and bb.YMin - eps <= p.y <= bb.YMax + eps and
                          bb.ZMin - eps <= p.z <= bb.ZMax + eps for p in m.Nodes.values())
    FreeCAD.closeDocument(doc.Name)
    return r
try:
    r = {"plate": inspect("$t/plate.FCStd", ["Plate"]), "several": inspect("$t/several.FCStd", ["Box", "Box001", "Fix_pin"]),
         "sheet": inspect("$t/sheet.FCStd", ["Sheet"])}
except Exception:
    r = {"error": traceback.format_exc()}
json.dump(r, open("$t/inspect.json", "w"))
sys.exit(0)
PY
(cd "$t" && freecadcmd fc_inspect.py > fc_inspect.log 2>&1)
if /usr/bin/python3 - "$t/inspect.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert "error" not in r, r["error"]
p = r["plate"]
print(json.dumps({k: v for k, v in p.items() if k != "faces_equal"}))
assert p["meshes"] == 1 and p["tets"] > 100 and p["in_analysis"], p
assert p["part"] == "Plate", p
assert "--hmax 3" in p["options"], p
assert sorted(p["faces_equal"]) == [f"Plate_Face{k}" for k in range(1, 8)] and all(p["faces_equal"].values()), p["faces_equal"]
assert p["volumes"]["Plate"] == p["tets"], p
assert not any(g.startswith(("FACE", "SOLID", "Face", "Solid")) for g in p["groups"]), p["groups"]
assert p["inside"], "a node outside the shape's bounding box"
PY
then ok plate-link-and-names; else bad plate-link-and-names; fi
if /usr/bin/python3 - "$t/inspect.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["several"]
print(json.dumps({k: v for k, v in s.items() if k not in ("faces_equal", "groups")}))
assert s["meshes"] == 1, s
assert s["part_type"] == "Part::Compound" and s["part_links"] == ["Box", "Box001", "Fix_pin"], s
bad = [k for k, v in s["faces_equal"].items() if not v]
assert len(s["faces_equal"]) == 6 + 6 + 3 and not bad, bad
assert all(s["volumes"][n] > 0 for n in ("Box", "Box001", "Fix_pin")), s["volumes"]
assert sum(s["volumes"].values()) == s["tets"], s
PY
then ok several-objects-names; else bad several-objects-names; fi
if /usr/bin/python3 - "$t/inspect.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["sheet"]
print(json.dumps(s))
assert s["meshes"] == 1 and s["tets"] == 0 and s["part"] == "Sheet", s
assert s["faces_equal"] == {"Sheet_Face1": True} and s["volumes"]["Sheet"] > 10, s
assert sorted(s["groups"]) == ["Sheet", "Sheet_Face1", "Sheet_Face1_Faces"], s
PY
then ok sheet-surface-names; else bad sheet-surface-names; fi

# 3. FreeCAD's CalculiX workflow on the macro's mesh
(cd "$t" && timeout 300 freecadcmd "$proj/tests/freecad/freecad_ccx.py" "$t/ccx.json" > ccx.log 2>&1)
if /usr/bin/python3 - "$t/ccx.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
assert "error" not in r, r["error"]
print(json.dumps({k: r[k] for k in ("part", "tets", "prerequisites", "ccx_exit", "ccx_job_finished", "ux_max", "console", "summary")}))
assert r["part"] == "Box" and r["in_analysis"], r
assert all(r["face_nodes_match"].values()), r["face_nodes_match"]
assert r["console"] == [], r["console"]   # no "Not all methods do work", no other warning
assert r["prerequisites"] == "" and r["ccx_exit"] == 0 and r["ccx_job_finished"], r
exact = 1000.0 * 40 / (210000.0 * 10 * 10)
assert abs(r["ux_max"] - exact) < 0.03 * exact, (r["ux_max"], exact)
PY
then ok calculix-workflow; else bad "calculix-workflow: $(tail -5 "$t/ccx.log")"; fi

# 4. the dialog's defaults are the CLI's (pure Python: no FreeCAD needed)
if PYTHONPATH="$proj/tools/freecad" /usr/bin/python3 - "$cli" <<'PY'
import sys
from anisomesh_options import cli_defaults, dialog_defaults, options_from_settings
d = cli_defaults(sys.argv[1])
shown = dialog_defaults(d, 50.0)
print(shown)
assert shown["hmax"] == float(d["--hmax-rel"]) * 50.0 and shown["hmin"] == float(d["--hmin-rel"]) * 50.0, shown
assert shown["elements_per_circle"] == float(d["--elements-per-circle"]) and shown["order"] == int(d["--order"]), shown
untouched = dict(shown, surface=False, quad=False)
assert options_from_settings(untouched, shown) == [], options_from_settings(untouched, shown)
changed = dict(untouched, hmax=2.0, order=2)
assert options_from_settings(changed, shown) == ["--hmax", "2.0", "--order", "2"], options_from_settings(changed, shown)
assert options_from_settings(dict(untouched, quad=True), shown) == ["--quad", "--dim", "2"]
PY
then ok dialog-defaults-from-cli; else bad dialog-defaults-from-cli; fi

# 5. a failing run (absurd option: the CLI exits 2) creates nothing and exits non-zero
(cd "$t" && ANISOMESH_DOCUMENT="$t/in.FCStd" ANISOMESH_OBJECTS=Plate ANISOMESH_OPTIONS="--hmax -3" \
   ANISOMESH_SAVE="$t/fail.FCStd" timeout 300 freecadcmd "$macro" > fail.log 2>&1); rc=$?
if [ $rc -ne 0 ] && [ ! -e "$t/fail.FCStd" ] && grep -q "anisomesh: .*hmax" "$t/fail.log"; then ok failure-creates-nothing
else bad "failure-creates-nothing: exit $rc: $(grep anisomesh "$t/fail.log" | tail -2)"; fi
(cd "$t" && ANISOMESH_DOCUMENT="$t/in.FCStd" ANISOMESH_OBJECTS=NoSuchThing \
   timeout 300 freecadcmd "$macro" > missing.log 2>&1); rc=$?
if [ $rc -ne 0 ] && grep -q "no object named NoSuchThing" "$t/missing.log"; then ok unknown-object
else bad "unknown-object: exit $rc"; fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
