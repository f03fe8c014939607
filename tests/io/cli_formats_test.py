#!/usr/bin/python3
"""Surface meshes from the real surface mesher, written by the CLI in every format, read by
the real clients with the same counts.

usage: cli_formats_test.py CLI MODELS_DIR [--dim 2|3]

Meshes models/plate.step and models/assembly2.step once per output format (the mesher is
deterministic, so every file holds the same mesh) and checks:
  - Gmsh 4.8 opens the MSH 4.1 (ASCII, binary) and 2.2 (ASCII, binary) files and the UNV:
    the same node and element counts in all, physical groups FACE1..FACE<n> and, in 3D, one
    named volume per solid;
  - meshio reads the INP, VTU (ASCII and base64), MSH, STL, OBJ and OFF with those counts;
  - the INP has an element set per face (2D) or per solid (3D), a node set per face and
    one per CAD edge whose nodes lie on that edge (inside its bounding box);
  - with --order 2, Gmsh (MSH 4.1, 2.2, UNV) and meshio (VTU) find the same numbers of
    quadratic elements;
  - in 2D, quad-dominant meshes (--quad, linear and --order 2): the same quads and triangles
    in Gmsh (MSH 4.1, 2.2, UNV) and meshio (INP, VTU, OBJ; STL with the quads split).
"""
import json, os, subprocess, sys
import meshio

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklib import Checks, scratch

cli, models = sys.argv[1], sys.argv[2]
dim = int(sys.argv[sys.argv.index("--dim") + 1]) if "--dim" in sys.argv else 2
t = scratch("aniso_cli_formats_")
check = Checks()


GM = r'''
import gmsh, sys, json
gmsh.initialize(); gmsh.option.setNumber("General.Terminal", 0)
res = {}
for path in sys.argv[1:]:
    gmsh.clear(); gmsh.open(path)
    r = {"nodes": len(gmsh.model.mesh.getNodes()[0]), "types": {}}
    for d in (2, 3):
        for e, tg in zip(*gmsh.model.mesh.getElements(d)[:2]):
            r["types"][str(e)] = r["types"].get(str(e), 0) + len(tg)
    r["phys"] = [[d, gmsh.model.getPhysicalName(d, g)] for d, g in gmsh.model.getPhysicalGroups()]
    res[path] = r
gmsh.finalize(); print(json.dumps(res))
'''
open(f"{t}/gm.py", "w").write(GM)

VARIANTS = [("a.msh", []), ("b.msh", ["--binary"]), ("c.msh", ["--msh-version", "2.2"]),
            ("d.msh", ["--msh-version", "2.2", "--binary"]), ("e.inp", []), ("f.vtu", []),
            ("g.vtu", ["--binary"]), ("h.unv", []), ("i.stl", []), ("j.stl", ["--binary"]),
            ("k.obj", []), ("l.off", [])]

for model, faces, solids in (("plate.step", 7, ["PLATE"]), ("assembly2.step", 12, ["BASE", "BLOCK"])):
    stem = os.path.splitext(model)[0]
    files = []
    for name, extra in VARIANTS:
        out = f"{t}/{stem}_{name}"
        p = subprocess.run([cli, "mesh", os.path.join(models, model), "-o", out, "--dim", str(dim), "--hmax", "4", "-q"] + extra,
                           capture_output=True, text=True, timeout=600)
        check(f"{stem} {name} written", p.returncode == 0 and os.path.exists(out), p.stderr.strip()[-200:])
        files.append(out)
    p = subprocess.run(["/usr/bin/python3", f"{t}/gm.py"] + [f for f in files if f.endswith((".msh", ".unv"))],
                       capture_output=True, text=True, timeout=600)
    check(f"{stem} gmsh", p.returncode == 0, p.stderr[-300:])
    gm = json.loads(p.stdout.strip().splitlines()[-1]) if p.returncode == 0 else {}
    ref = gm.get(files[0])
    if ref is None:
        continue
    types = ref["types"]
    tris, tets = types.get("2", 0), types.get("4", 0)
    check(f"{stem} elements", tris > 0 and (tets > 0) == (dim == 3), f"{types}")
    for f in files:
        if not f.endswith((".msh", ".unv")): continue
        r = gm.get(f, {})
        check(f"gmsh {os.path.basename(f)} counts", r.get("nodes") == ref["nodes"] and r.get("types") == types,
              f"{r.get('nodes')} nodes {r.get('types')} vs {ref['nodes']} {types}")
        if f.endswith(".msh"):
            names2 = sorted(n for d, n in r["phys"] if d == 2)
            names3 = [n for d, n in r["phys"] if d == 3]
            check(f"gmsh {os.path.basename(f)} face groups", names2 == sorted(f"FACE{i}" for i in range(1, faces + 1)), f"{names2}")
            check(f"gmsh {os.path.basename(f)} solid groups", names3 == (solids if dim == 3 else []), f"{names3}")
    for f in files:
        ext = os.path.splitext(f)[1]
        if ext == ".unv": continue  # meshio 5.0 has no UNV reader
        try:
            m = meshio.read(f)
        except Exception as ex:
            check(f"meshio {os.path.basename(f)}", False, str(ex)[:200]); continue
        counts = {}
        for cb in m.cells: counts[cb.type] = counts.get(cb.type, 0) + len(cb.data)
        if ext in (".stl", ".obj", ".off"):
            want = {"triangle": tris}
        elif ext == ".inp" and dim == 3:
            want = {"tetra": tets}
        else:
            want = {k: v for k, v in (("triangle", tris), ("tetra", tets)) if v}
        check(f"meshio {os.path.basename(f)} counts", counts == want, f"{counts} != {want}")
        if ext in (".msh", ".inp", ".vtu"):
            check(f"meshio {os.path.basename(f)} nodes", len(m.points) == ref["nodes"], f"{len(m.points)} != {ref['nodes']}")
        if ext == ".inp":
            nsets = sorted(k for k in m.point_sets if k.startswith("FACE"))
            check(f"meshio {os.path.basename(f)} node sets", nsets == sorted(f"FACE{i}" for i in range(1, faces + 1)), f"{nsets}")
            esets = sorted(k for k in m.cell_sets if k != "EALL")
            want_sets = sorted(solids) if dim == 3 else sorted(f"FACE{i}" for i in range(1, faces + 1))
            check(f"meshio {os.path.basename(f)} element sets", esets == want_sets, f"{esets}")
            # a node set per CAD edge, its nodes on that edge (inside its bounding box)
            info = subprocess.run([cli, "info", os.path.join(models, model), "--faces", "--json"],
                                  capture_output=True, text=True, timeout=600)
            edges = json.loads(info.stdout)["edge_list"] if info.returncode == 0 else []
            esets_n = sorted(k for k in m.point_sets if k.startswith("EDGE"))
            check(f"meshio {os.path.basename(f)} edge node sets", edges and esets_n == sorted(f"EDGE{e['id']}" for e in edges),
                  f"{len(esets_n)} sets for {len(edges)} edges")
            off = []
            for e in edges:
                ids = m.point_sets.get(f"EDGE{e['id']}", [])
                lo, hi = e["bbox"]["min"], e["bbox"]["max"]
                if len(ids) < 2 or any(not all(lo[k] - 1e-6 <= m.points[i][k] <= hi[k] + 1e-6 for k in range(3)) for i in ids):
                    off.append(e["id"])
            check(f"meshio {os.path.basename(f)} edge node sets on their edges", not off, f"edges {off[:5]}")

    # Quadratic: the same mesh elevated (--order 2) keeps its element counts.
    quad_files = []
    for name, extra in (("q.msh", []), ("r.msh", ["--msh-version", "2.2"]), ("s.vtu", []), ("u.unv", [])):
        out = f"{t}/{stem}_{name}"
        p = subprocess.run([cli, "mesh", os.path.join(models, model), "-o", out, "--dim", str(dim), "--hmax", "4", "-q",
                            "--order", "2"] + extra, capture_output=True, text=True, timeout=600)
        check(f"{stem} {name} (order 2) written", p.returncode == 0 and os.path.exists(out), p.stderr.strip()[-200:])
        quad_files.append(out)
    want_types = {k: v for k, v in (("9", tris), ("11", tets)) if v}
    p = subprocess.run(["/usr/bin/python3", f"{t}/gm.py"] + [f for f in quad_files if not f.endswith(".vtu")],
                       capture_output=True, text=True, timeout=600)
    gq = json.loads(p.stdout.strip().splitlines()[-1]) if p.returncode == 0 else {}
    for f in quad_files:
        if f.endswith(".vtu"):
            try:
                m = meshio.read(f)
                counts = {cb.type: len(cb.data) for cb in m.cells}
            except Exception as ex:
                counts = str(ex)[:100]
            want = {k: v for k, v in (("triangle6", tris), ("tetra10", tets)) if v}
            check(f"meshio {os.path.basename(f)} (order 2) counts", counts == want, f"{counts} != {want}")
        else:
            r = gq.get(f, {})
            check(f"gmsh {os.path.basename(f)} (order 2) counts", r.get("types") == want_types, f"{r.get('types')} != {want_types}")

# Quad-dominant surfaces (--quad), linear and quadratic: the same counts in every reader.
if dim == 2:
    for order in ("1", "2"):
        files = []
        for name in ("a.msh", "b.msh", "c.unv", "d.inp", "e.vtu", "f.obj", "g.stl"):
            out = f"{t}/quad{order}_{name}"
            extra = ["--msh-version", "2.2"] if name == "b.msh" else []
            p = subprocess.run([cli, "mesh", os.path.join(models, "plate.step"), "-o", out, "--dim", "2", "--quad",
                                "--hmax", "4", "--order", order, "-q"] + extra, capture_output=True, text=True, timeout=600)
            check(f"--quad --order {order} {name} written", p.returncode == 0, p.stderr.strip()[-200:])
            files.append(out)
        p = subprocess.run(["/usr/bin/python3", f"{t}/gm.py"] + files[:3], capture_output=True, text=True, timeout=600)
        gq = json.loads(p.stdout.strip().splitlines()[-1]) if p.returncode == 0 else {}
        ref = gq.get(files[0], {}).get("types", {})
        tris, quads = ref.get("2" if order == "1" else "9", 0), ref.get("3" if order == "1" else "16", 0)
        check(f"--quad --order {order} quads", quads > 10 * tris and tris + quads == sum(ref.values()), f"{ref}")
        for f in files[1:3]:
            check(f"gmsh {os.path.basename(f)} counts", gq.get(f, {}).get("types") == ref, f"{gq.get(f)} != {ref}")
        for f in files[3:]:
            if f.endswith(".inp") and order == "2": continue  # S6/S8 unknown to meshio 5.0
            try:
                m = meshio.read(f)
                counts = {}
                for cb in m.cells: counts[cb.type] = counts.get(cb.type, 0) + len(cb.data)
            except Exception as ex:
                counts = str(ex)[:100]
            if f.endswith(".stl"):
                want = {"triangle": tris + 2 * quads}
            elif f.endswith(".obj") or order == "1":
                want = {k: v for k, v in (("triangle", tris), ("quad", quads)) if v}
            else:
                want = {k: v for k, v in (("triangle6", tris), ("quad8", quads)) if v}
            check(f"meshio {os.path.basename(f)} counts", counts == want, f"{counts} != {want}")

check.finish(f"cli formats (dim {dim})", 40)
