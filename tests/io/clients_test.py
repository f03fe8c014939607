#!/usr/bin/python3
"""The real clients read what our writers write.

usage: clients_test.py IO_WRITE_FIXTURES

io_write_fixtures writes hand-made meshes (a box of Kuhn tetrahedra, linear and quadratic;
its surface as quads and triangles, linear and quadratic; that surface without face 6's
elements but with its nodes; three boxes named nut, nut, bolt)
in every format and variant, with manifest.json saying what each holds. Then:
  - Gmsh 4.8 (python3-gmsh) opens every MSH (4.1 ASCII/binary, 2.2 ASCII/binary) and the
    UNV: same node and element counts by type, the physical groups FACE1..FACE6 and the
    solids' names (unique: nut, nut_2, bolt), mid-edge nodes at the middle of the edges
    Gmsh's node order puts them on, tetrahedra positively oriented;
  - meshio (python3-meshio) reads the INP, VTU (ASCII and base64), MSH, STL, OBJ and OFF:
    same counts, the INP's node sets FACE<n> and element sets per solid, the VTU's cell data,
    mid-edge nodes where VTK's order puts them;
  - VTK 9 (python3-vtk9: ParaView's XML reader) reads every VTU: cell types and counts, the
    cell data, and the cells' volumes and areas (VTK's own isoparametric integration, so a
    wrong quadratic node order shows) add up to the boxes' volume and surface area.
meshio 5.0 has no UNV reader, no S6/S8 element types and reads only triangle OFF files:
UNV files are read by Gmsh only; quadratic shell INP files and OFF files with quads are not
read by a client here.
"""
import json, os, subprocess, sys
import numpy as np
import meshio

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import Checks, scratch

fixtures = sys.argv[1]
out = scratch("aniso_clients_")
subprocess.run([fixtures, out], check=True)
manifest = json.load(open(os.path.join(out, "manifest.json")))
check = Checks()


# Mid-edge nodes by reader convention: (position, corner a, corner b)
GMSH_MIDS = {9: [(3, 0, 1), (4, 1, 2), (5, 2, 0)], 16: [(4, 0, 1), (5, 1, 2), (6, 2, 3), (7, 3, 0)],
             11: [(4, 0, 1), (5, 1, 2), (6, 2, 0), (7, 3, 0), (8, 3, 2), (9, 3, 1)]}
VTK_MIDS = {"triangle6": GMSH_MIDS[9], "quad8": GMSH_MIDS[16],
            "tetra10": [(4, 0, 1), (5, 1, 2), (6, 2, 0), (7, 0, 3), (8, 1, 3), (9, 2, 3)]}


def mids_ok(points, cells, mids):
    """Largest distance of a mid-edge node from the middle of its edge, relative to the edge."""
    worst = 0.0
    for m, a, b in mids:
        edge = np.linalg.norm(points[cells[:, a]] - points[cells[:, b]], axis=1)
        d = np.linalg.norm(points[cells[:, m]] - 0.5 * (points[cells[:, a]] + points[cells[:, b]]), axis=1)
        worst = max(worst, float((d / edge).max()))
    return worst < 1e-12


def tets_positive(points, cells):
    p = points
    v = np.einsum("ij,ij->i", p[cells[:, 1]] - p[cells[:, 0]],
                  np.cross(p[cells[:, 2]] - p[cells[:, 0]], p[cells[:, 3]] - p[cells[:, 0]]))
    return bool((v > 0).all())


# ---------------------------------------------------------------- Gmsh
GMSH_SCRIPT = r'''
import gmsh, sys, json
import numpy as np
gmsh.initialize(); gmsh.option.setNumber("General.Terminal", 0)
res = {}
for path in sys.argv[1:]:
    gmsh.clear(); gmsh.open(path)
    tags, coords, _ = gmsh.model.mesh.getNodes()
    pts = {int(t): coords[3*i:3*i+3].tolist() for i, t in enumerate(tags)}
    r = {"nodes": len(tags), "types": {}, "phys": [], "conn": {}}
    for dim in (2, 3):
        et, etags, enodes = gmsh.model.mesh.getElements(dim)
        for e, tg, nd in zip(et, etags, enodes):
            r["types"][str(e)] = r["types"].get(str(e), 0) + len(tg)
            r["conn"].setdefault(str(e), []).extend(int(n) for n in nd)
    r["phys"] = [[d, t, gmsh.model.getPhysicalName(d, t)] for d, t in gmsh.model.getPhysicalGroups()]
    r["points"] = pts
    res[path] = r
gmsh.finalize()
print(json.dumps(res))
'''
script = os.path.join(out, "gmsh_read.py")
open(script, "w").write(GMSH_SCRIPT)
gmsh_files = [os.path.join(out, f) for case in manifest.values() for f in case["files"]
              if f.endswith(".msh") or f.endswith(".unv")]
p = subprocess.run(["/usr/bin/python3", script] + gmsh_files, capture_output=True, text=True, timeout=500)
check("gmsh runs", p.returncode == 0, p.stderr[-300:])
gm = json.loads(p.stdout.strip().splitlines()[-1]) if p.returncode == 0 else {}

NPER = {2: 3, 9: 6, 3: 4, 16: 8, 4: 4, 11: 10}
for name, case in manifest.items():
    q = case["quadratic"]
    want = {}
    if case["triangles"]: want[9 if q else 2] = case["triangles"]
    if case["quads"]: want[16 if q else 3] = case["quads"]
    if case["tets"]: want[11 if q else 4] = case["tets"]
    for f in case["files"]:
        if not (f.endswith(".msh") or f.endswith(".unv")): continue
        r = gm.get(os.path.join(out, f))
        if r is None:
            check(f"gmsh {f}", False, "not read"); continue
        # MSH 4.1 keeps nodes classified on an entity without elements; Gmsh drops them from 2.2 and UNV
        want_nodes = case["nodes"] if f.endswith(".msh") and "_22" not in f else case["used_nodes"]
        check(f"gmsh {f} nodes", r["nodes"] == want_nodes, f"{r['nodes']} != {want_nodes}")
        got = {int(k): v for k, v in r["types"].items()}
        check(f"gmsh {f} elements", got == want, f"{got} != {want}")
        pts = {int(k): np.array(v) for k, v in r["points"].items()}
        for e, conn in r["conn"].items():
            e = int(e)
            tags = np.array(conn).reshape(-1, NPER[e])
            keys = sorted(pts)
            index = {k: i for i, k in enumerate(keys)}
            P = np.array([pts[k] for k in keys])
            C = np.vectorize(index.get)(tags)
            if e in GMSH_MIDS:
                check(f"gmsh {f} type {e} node order", mids_ok(P, C, GMSH_MIDS[e]), "mid-edge nodes off their edges")
            if e in (4, 11):
                check(f"gmsh {f} tets positive", tets_positive(P, C), "negative volume")
        if f.endswith(".msh"):
            faces = sorted(n for d, t, n in r["phys"] if d == 2)
            solids = [n for d, t, n in sorted(r["phys"]) if d == 3]
            want_faces = sorted(case["face_groups"])
            check(f"gmsh {f} face groups", faces == want_faces, f"{faces}")
            check(f"gmsh {f} solid groups", solids == case["solid_names"], f"{solids} != {case['solid_names']}")

# ---------------------------------------------------------------- meshio
TRI = {False: "triangle", True: "triangle6"}
QUAD = {False: "quad", True: "quad8"}
TET = {False: "tetra", True: "tetra10"}
for name, case in manifest.items():
    q = case["quadratic"]
    volume = case["tets"] > 0
    for f in case["files"]:
        ext = os.path.splitext(f)[1]
        if ext == ".unv": continue  # no UNV reader in meshio 5.0
        if ext == ".inp" and q and not volume: continue  # S6/S8 unknown to meshio 5.0
        if ext == ".off" and case["quads"]: continue  # meshio 5.0 reads triangle-only OFF (exits otherwise)
        try:
            m = meshio.read(os.path.join(out, f))
        except Exception as ex:
            check(f"meshio {f}", False, str(ex)[:200]); continue
        counts = {}
        for cb in m.cells: counts[cb.type] = counts.get(cb.type, 0) + len(cb.data)
        if ext in (".stl", ".obj", ".off"):
            if ext == ".stl":
                want = {"triangle": case["triangles"] + 2 * case["quads"]}
            else:
                want = {k: v for k, v in (("triangle", case["triangles"]), ("quad", case["quads"])) if v}
            check(f"meshio {f} elements", counts == want, f"{counts} != {want}")
            if ext != ".stl":
                check(f"meshio {f} points", len(m.points) == case["corner_nodes"], f"{len(m.points)} != {case['corner_nodes']}")
            continue
        want = {}
        if ext == ".inp" and volume:
            want[TET[q]] = case["tets"]  # 3D decks: 3D elements only
        else:
            if case["triangles"]: want[TRI[q]] = case["triangles"]
            if case["quads"]: want[QUAD[q]] = case["quads"]
            if case["tets"]: want[TET[q]] = case["tets"]
        check(f"meshio {f} elements", counts == want, f"{counts} != {want}")
        check(f"meshio {f} points", len(m.points) == case["nodes"], f"{len(m.points)} != {case['nodes']}")
        P = np.asarray(m.points, float)
        for cb in m.cells:
            C = np.asarray(cb.data)
            if cb.type in VTK_MIDS:
                check(f"meshio {f} {cb.type} node order", mids_ok(P, C, VTK_MIDS[cb.type]), "mid-edge nodes off their edges")
            if cb.type in ("tetra", "tetra10"):
                check(f"meshio {f} tets positive", tets_positive(P, C), "negative volume")
        if ext == ".inp":
            faces = sorted(k for k in m.point_sets if k.startswith("FACE"))
            check(f"meshio {f} node sets", faces == sorted(case["face_groups"]), f"{faces}")
            if volume:
                sets = [k for k in m.cell_sets if k != "EALL"]
                check(f"meshio {f} element sets", sets == case["solid_names"] and "EALL" in m.cell_sets,
                      f"{list(m.cell_sets)}")
        if ext == ".vtu":
            cd = m.cell_data
            check(f"meshio {f} cell data", all(k in cd for k in ("region", "face", "quality")), f"{list(cd)}")
            if all(k in cd for k in ("region", "face", "quality")):
                for cb, reg, fc, qual in zip(m.cells, cd["region"], cd["face"], cd["quality"]):
                    is_tet = cb.type.startswith("tetra")
                    check(f"meshio {f} {cb.type} ids", (reg > 0).all() == is_tet and (fc > 0).all() != is_tet,
                          "region set on tetrahedra only, face on boundary elements only")
                    check(f"meshio {f} {cb.type} quality", ((qual > 0) & (qual <= 1 + 1e-12)).all(), "quality out of (0, 1]")

# ---------------------------------------------------------------- VTK (ParaView's reader)
import vtk
from vtk.util.numpy_support import vtk_to_numpy
VTK_TYPES = {False: (5, 9, 10), True: (22, 23, 24)}
for name, case in manifest.items():
    q = case["quadratic"]
    size = np.array([10.0, 3.0, 2.0])  # the fixtures' box
    boxes = max(case["solids"], 1)
    surface = 2 * (size[0] * size[1] + size[1] * size[2] + size[0] * size[2]) - (size[0] * size[1] if name == "open" else 0)
    for f in case["files"]:
        if not f.endswith(".vtu"): continue
        errors = []
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.AddObserver("ErrorEvent", lambda obj, ev: errors.append(ev))
        reader.GetExecutive().AddObserver("ErrorEvent", lambda obj, ev: errors.append(ev))
        reader.SetFileName(os.path.join(out, f))
        reader.Update()
        g = reader.GetOutput()
        check(f"vtk {f} reads", not errors and g.GetNumberOfPoints() == case["nodes"],
              f"{errors} {g.GetNumberOfPoints()} points")
        types = vtk_to_numpy(g.GetCellTypesArray()) if g.GetNumberOfCells() else np.array([])
        tri, quad, tet = VTK_TYPES[q]
        want = {tri: case["triangles"], quad: case["quads"], tet: case["tets"]}
        got = {t: int((types == t).sum()) for t in want}
        check(f"vtk {f} cells", got == want and len(types) == sum(want.values()), f"{got} != {want}")
        cd = g.GetCellData()
        check(f"vtk {f} cell data", all(cd.GetArray(a) is not None for a in ("region", "face", "quality")),
              "region, face, quality")
        sizes = vtk.vtkCellSizeFilter()
        sizes.SetInputData(g)
        sizes.Update()
        o = sizes.GetOutput().GetCellData()
        volume = float(vtk_to_numpy(o.GetArray("Volume")).sum())
        area = float(vtk_to_numpy(o.GetArray("Area")).sum())
        want_v = boxes * np.prod(size) if case["tets"] else 0.0
        want_a = boxes * surface
        check(f"vtk {f} volume and area", abs(volume - want_v) < 1e-9 * want_a and abs(area - want_a) < 1e-9 * want_a,
              f"volume {volume} (want {want_v}), area {area} (want {want_a})")

check.finish("io clients", 50)
