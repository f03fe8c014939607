#!/bin/bash
# FreeCAD's FEM workbench (SMESH's UNV driver, what FreeCAD uses for Gmsh's meshes) imports
# the UNV files io_write_fixtures writes: node and element counts as in manifest.json, a
# node group and an element group per CAD face (SMESH names them FACE<n>_Nodes and
# FACE<n>_Faces), a volume group per solid under its unique part name (nut, nut_2, bolt),
# and the quadratic box's volume (FemMesh.Volume) is the box's 60.
# usage: freecad_unv_test.sh IO_WRITE_FIXTURES
fixtures=$1
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
export HOME=$t
"$fixtures" "$t" > "$t/fixtures.log" 2>&1 || { echo "io_write_fixtures failed"; exit 1; }
cat > "$t/read.py" <<PY
import Fem, json
res = {}
for name in ["tet4", "tet10", "quad4", "quad8", "open", "parts"]:
    fm = Fem.read("$t/%s.unv" % name)
    fm = getattr(fm, "FemMesh", fm)
    groups = {fm.getGroupName(g): [fm.getGroupElementType(g), len(fm.getGroupElements(g))] for g in fm.Groups}
    res[name] = {"nodes": fm.NodeCount, "tets": fm.TetraCount, "triangles": fm.TriangleCount,
                 "quads": fm.QuadrangleCount, "volume": float(fm.Volume.Value), "groups": groups}
open("$t/freecad.json", "w").write(json.dumps(res))
PY
(cd "$t" && timeout 300 freecadcmd read.py > freecad.log 2>&1)
[ -f "$t/freecad.json" ] || { echo "FreeCAD did not read the UNV files: $(grep -m1 -i exception "$t/freecad.log")"; exit 1; }
/usr/bin/python3 - "$t/manifest.json" "$t/freecad.json" <<'PY'
import json, sys
man, fc = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
bad = []
for name, case in man.items():
    r = fc[name]
    for k in ("nodes", "tets", "triangles", "quads"):
        if r[k] != case[k]: bad.append(f"{name}: {k} {r[k]} != {case[k]}")
    g = r["groups"]
    for f in case["face_groups"]:
        if g.get(f"{f}_Nodes", ["", 0])[0] != "Node" or g.get(f"{f}_Faces", ["", 0])[0] != "Face":
            bad.append(f"{name}: no node and face groups for {f}")
    for s in case["solid_names"]:
        if g.get(s, [""])[0] != "Volume" or g[s][1] != case["tets"] // len(case["solid_names"]):
            bad.append(f"{name}: volume group {s}: {g.get(s)}")
    if name == "tet10" and abs(r["volume"] - 60.0) > 1e-9:
        bad.append(f"tet10: FreeCAD volume {r['volume']} != 60")
for b in bad: print("FAIL", b)
print(f"FreeCAD UNV import: {len(man) - len({b.split(':')[0] for b in bad})}/{len(man)} meshes as written")
sys.exit(1 if bad else 0)
PY
