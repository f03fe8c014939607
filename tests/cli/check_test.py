"""anisomesh check: files written by Gmsh, meshio and our own `anisomesh mesh` are read with
the counts meshio finds (by type and by physical group), their quality agrees with the
referee (meshq.py), a deliberately inverted or flipped element gives exit 3, and garbage,
truncated, empty or unknown files give exit 2 with one line naming the file.

usage: check_test.py ANISOMESH SHARED_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

import meshio
import numpy as np

CLI, SHARED = sys.argv[1], sys.argv[2]
failures = []
checks = 0


def check(name, ok, detail=""):
    global checks
    checks += 1
    if not ok:
        failures.append(f"{name}: {detail}")


def run(*args):
    p = subprocess.run([CLI, *args], capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def check_json(path):
    rc, out, err = run("check", path, "--json")
    try:
        return rc, json.loads(out), err
    except ValueError:
        return rc, None, err


# meshio's cell type names -> ours
TYPES = {"vertex": "point", "line": "line", "line3": "line3", "triangle": "triangle", "triangle6": "triangle6",
         "quad": "quad", "quad8": "quad8", "quad9": "quad9", "tetra": "tet", "tetra10": "tet10"}


def meshio_counts(path):
    m = meshio.read(path)
    counts = {}
    for block in m.cells:
        counts[TYPES[block.type]] = counts.get(TYPES[block.type], 0) + len(block.data)
    return m, counts


def gmsh_groups(m):
    """Element counts by type per Gmsh physical group, as meshio reads them."""
    if "gmsh:physical" not in m.cell_data:
        return {}
    names = {(int(v[1]), int(v[0])): k for k, v in m.field_data.items()}
    groups = {}
    for block, tags in zip(m.cells, m.cell_data["gmsh:physical"]):
        dim = 3 if block.type.startswith("tetra") else 2 if block.type.startswith(("tri", "quad")) else 1
        for tag, n in zip(*np.unique(tags, return_counts=True)):
            if tag == 0:
                continue
            name = names.get((dim, int(tag)), f"{dim}:{tag}")
            g = groups.setdefault(name, {})
            g[TYPES[block.type]] = g.get(TYPES[block.type], 0) + int(n)
    return groups


def expect_same_counts(label, path, groups=True, must_be_valid=True):
    rc, j, err = check_json(path)
    if must_be_valid:
        check(f"{label} exit", rc == 0, f"exit {rc} {err.strip()} {j and j['problems']}")
    else:  # the exit code says what the JSON says
        check(f"{label} exit", j is not None and rc == (0 if j["valid"] else 3), f"exit {rc} {err.strip()}")
    if j is None:
        return None
    m, counts = meshio_counts(path)
    check(f"{label} counts", j["elements"] == counts, f"check {j['elements']} meshio {counts}")
    if groups and path.endswith(".msh"):
        ours = {g["name"]: g["elements"] for g in j["groups"]}
        theirs = gmsh_groups(m)
        check(f"{label} groups", ours == theirs, f"check {ours} meshio {theirs}")
    return j


GEO = """SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Sphere(2) = {2.5, 0.5, 0.5, 0.5};
Physical Volume("box") = {1};
Physical Volume("ball") = {2};
Physical Surface("skin") = {1, 2, 3, 7};
Mesh.MeshSizeMax = 0.25;
"""
QUAD_GEO = """SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 2, 1};
Disk(2) = {3.5, 0.5, 0, 0.5};
Physical Surface("plate") = {1};
Physical Surface("disk") = {2};
Mesh.MeshSizeMax = 0.2;
Mesh.RecombineAll = 1;
"""

with tempfile.TemporaryDirectory() as t:
    geo, qgeo = os.path.join(t, "m.geo"), os.path.join(t, "q.geo")
    open(geo, "w").write(GEO)
    open(qgeo, "w").write(QUAD_GEO)
    gmsh_files = {
        "g41.msh": ["-3"], "g41b.msh": ["-3", "-bin"], "g22.msh": ["-3", "-format", "msh22"],
        "g22b.msh": ["-3", "-format", "msh22", "-bin"], "g41q.msh": ["-3", "-order", "2"],
        "g41qb.msh": ["-3", "-order", "2", "-bin"],
    }
    for name, opts in gmsh_files.items():
        out = os.path.join(t, name)
        subprocess.run(["gmsh", geo, *opts, "-o", out], capture_output=True, check=True)
        j = expect_same_counts(f"gmsh {name}", out)
        if j:
            check(f"gmsh {name} valid", j["valid"] and j["surface"]["of"] == "volume boundary" and j["surface"]["closed"],
                  json.dumps(j["surface"]))
    for name, opts in {"quad.msh": ["-2"], "quad8.msh": ["-2", "-order", "2", "-setnumber", "Mesh.SecondOrderIncomplete", "1"]}.items():
        out = os.path.join(t, name)
        subprocess.run(["gmsh", qgeo, *opts, "-o", out], capture_output=True, check=True)
        j = expect_same_counts(f"gmsh {name}", out)
        if j:
            q = j["quality"].get("quad_scaled_jacobian", {})
            check(f"gmsh {name} quads", q.get("count", 0) > 0 and q["min"] > 0 and j["valid"], json.dumps(q))

    # Quality agrees with the referee.
    g41 = os.path.join(t, "g41.msh")
    rc, j, _ = check_json(g41)
    ref = json.loads(subprocess.run(["/usr/bin/python3", os.path.join(SHARED, "tools", "meshq.py"), g41],
                                    capture_output=True, text=True).stdout.strip().splitlines()[-1])
    tq = j["quality"]["tet_mean_ratio"]
    check("referee tet eta", abs(tq["min"] - ref["eta_min"]) < 1e-3 and abs(tq["avg"] - ref["eta_avg"]) < 1e-3,
          f"{tq} vs {ref}")
    check("referee dihedral", abs(j["quality"]["tet_dihedral_deg"]["min"] - ref["dihedral_min"]) < 0.1,
          f"{j['quality']['tet_dihedral_deg']} vs {ref['dihedral_min']}")
    check("referee tri eta", abs(j["quality"]["triangle_mean_ratio"]["avg"] - ref["tri_eta_avg"]) < 1e-3,
          f"{j['quality']['triangle_mean_ratio']} vs {ref}")

    # meshio as a second writer: VTU ASCII and base64, INP, OFF with a comment.
    mq = meshio.read(os.path.join(t, "g41q.msh"))
    plain = meshio.Mesh(mq.points, mq.cells)
    for name, kw in {"mio_a.vtu": {"binary": False}, "mio_b.vtu": {"binary": True, "compression": None}}.items():
        meshio.write(os.path.join(t, name), plain, **kw)
        expect_same_counts(f"meshio {name}", os.path.join(t, name))
    meshio.write(os.path.join(t, "mio.inp"), plain)
    expect_same_counts("meshio inp", os.path.join(t, "mio.inp"))
    # meshio's default VTU: zlib-compressed base64 blocks.
    zpath = os.path.join(t, "mio_z.vtu")
    meshio.write(zpath, plain)
    check("meshio vtu is compressed", "vtkZLibDataCompressor" in open(zpath).read(), "meshio wrote no zlib VTU")
    expect_same_counts("meshio zlib vtu", zpath)
    # VTK's own writer: appended raw data, zlib, UInt64 headers, small blocks (many per array).
    try:
        import vtk
        from vtk.util.numpy_support import numpy_to_vtk
        lin = meshio.read(g41)
        vpts = vtk.vtkPoints()
        vpts.SetData(numpy_to_vtk(lin.points.astype("float64"), deep=True))
        grid = vtk.vtkUnstructuredGrid()
        grid.SetPoints(vpts)
        for block in lin.cells:
            vtype = {"triangle": vtk.VTK_TRIANGLE, "tetra": vtk.VTK_TETRA, "line": vtk.VTK_LINE,
                     "vertex": vtk.VTK_VERTEX}.get(block.type)
            if vtype is None:
                continue
            for cell in block.data:
                grid.InsertNextCell(vtype, len(cell), [int(i) for i in cell])
        w = vtk.vtkXMLUnstructuredGridWriter()
        w.SetFileName(os.path.join(t, "vtk_z.vtu"))
        w.SetInputData(grid)
        w.SetDataModeToAppended()
        w.EncodeAppendedDataOff()
        w.SetCompressorTypeToZLib()
        w.SetHeaderTypeToUInt64()
        w.SetBlockSize(4096)
        w.Write()
        expect_same_counts("vtk zlib appended vtu", os.path.join(t, "vtk_z.vtu"), groups=False)
    except ImportError:
        check("python3-vtk9 available", False, "import vtk failed")
    # A corrupt compressed block: a clear one-line error, exit 2.
    text = open(zpath).read()
    start = text.index(">", text.index("<DataArray")) + 1
    bad = text[:start + 12] + ("A" * 40) + text[start + 52:]
    open(os.path.join(t, "bad_z.vtu"), "w").write(bad)
    rc, out, err = run("check", os.path.join(t, "bad_z.vtu"))
    check("corrupt compressed vtu", rc == 2 and "bad_z.vtu" in err and len(err.strip().splitlines()) == 1,
          f"exit {rc} {err}")

    # Our own meshes, in every format we write.
    model = os.path.join(SHARED, "bench", "cube_1.step")
    outputs = ["s.msh", "sb.msh --binary", "s22.msh --msh-version 2.2", "s.inp", "s.vtu", "sb.vtu --binary",
               "s.stl", "s.obj", "s.off", "q.msh --order 2", "q.inp --order 2", "q.vtu --order 2"]
    for spec in outputs:
        name, *opts = spec.split()
        out = os.path.join(t, name)
        report = out + ".json"
        rc, _, err = run("mesh", model, "-o", out, "--dim", "2", "--hmax", "0.25", "-q", "--report", report, *opts)
        check(f"mesh {spec}", rc == 0, err)
        if rc == 0:
            # meshio cannot read S6 (Abaqus 6-node shells): there, the run report is the reference.
            if name == "q.inp":
                rc, j, err = check_json(out)
                want = {"triangle6": json.load(open(report))["counts"]["triangles"]}
                check("ours q.inp counts", rc == 0 and j and j["elements"] == want, f"exit {rc} {j and j['elements']} {want}")
            else:
                j = expect_same_counts(f"ours {spec}", out, groups=False)
            if j:
                check(f"ours {spec} closed", j["valid"] and j["surface"]["closed"] and j["surface"]["oriented"],
                      json.dumps(j["surface"]))
                if name.endswith(".msh"):
                    check(f"ours {spec} FACE groups", sorted(g["name"] for g in j["groups"]) ==
                          [f"FACE{i}" for i in range(1, 7)], str(j["groups"]))
    rc, _, err = run("mesh", model, "-o", os.path.join(t, "v.msh"), "--dim", "3", "--order", "2", "--hmax", "0.25", "-q")
    if rc == 0:  # the volume mesher is in this build
        j = expect_same_counts("ours volume tet10", os.path.join(t, "v.msh"), groups=False, must_be_valid=False)
        if j:
            # Degenerate (flat) tetrahedra are the volume mesher's to avoid; none may be inverted.
            check("ours volume not inverted", j["inverted"] == 0 and j["elements"].get("tet10", 0) > 0 and
                  j["surface"]["closed"] and j["surface"]["oriented"], f"{j['problems']} {j['surface']}")

    # Hand-written INP: *INCLUDE, lower-case keywords, a C3D10 continued on a second line,
    # GENERATE, a set made of sets; the two tetrahedra share a face.
    open(os.path.join(t, "nodes.inc"), "w").write(
        "*node, nset=NALL\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n5, 1, 1, 1\n")
    mids = {(1, 2): 11, (2, 3): 12, (3, 1): 13, (1, 4): 14, (2, 4): 15, (3, 4): 16}
    pts = {1: (0, 0, 0), 2: (1, 0, 0), 3: (0, 1, 0), 4: (0, 0, 1)}
    mid_lines = "".join(f"{n}, {(pts[a][0] + pts[b][0]) / 2}, {(pts[a][1] + pts[b][1]) / 2}, {(pts[a][2] + pts[b][2]) / 2}\n"
                        for (a, b), n in mids.items())
    open(os.path.join(t, "deck.inp"), "w").write(
        "** a deck\n*HEADING\ntest\n*INCLUDE, INPUT=nodes.inc\n*NODE\n" + mid_lines +
        "*ELEMENT, TYPE=C3D10, ELSET=quad\n1, 1, 2, 3, 4, 11, 12, 13,\n14, 15, 16\n"
        "*element, type=C3D4, elset=lin\n2, 2, 3, 4, 5\n"
        "*ELSET, ELSET=ALLT\nquad, lin\n*ELSET, ELSET=GEN, GENERATE\n1, 2, 1\n"
        "*NSET, NSET=CORNERS, GENERATE\n1, 5\n*STEP\n*STATIC\n*END STEP\n")
    rc, j, err = check_json(os.path.join(t, "deck.inp"))
    groups = {g["name"]: g["elements"] for g in j["groups"]} if j else {}
    check("inp deck", rc == 0 and j["elements"] == {"tet": 1, "tet10": 1} and j["nodes"] == 11 and
          groups == {"quad": {"tet10": 1}, "lin": {"tet": 1}, "ALLT": {"tet": 1, "tet10": 1}, "GEN": {"tet": 1, "tet10": 1}}
          and j["node_sets"] == {"NALL": 5, "CORNERS": 5} and j["surface"]["faces"] == 6,
          f"exit {rc} {err} {j}")

    # Hand-written VTU with appended data, raw and base64 (UInt32 headers), one tetrahedron.
    import base64
    import struct
    arrays = [("Float64", "", struct.pack("<12d", 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)),
              ("Int32", 'Name="connectivity"', struct.pack("<4i", 0, 1, 2, 3)),
              ("Int32", 'Name="offsets"', struct.pack("<i", 4)), ("UInt8", 'Name="types"', struct.pack("<B", 10)),
              ("Int32", 'Name="part"', struct.pack("<i", 7))]
    for encoding in ("raw", "base64"):
        blobs, offset, tags = [], 0, []
        for kind, name, data in arrays:
            blob = struct.pack("<I", len(data)) + data
            if encoding == "base64":
                blob = base64.b64encode(blob)
            extra = ' NumberOfComponents="3"' if name == "" else ""
            tags.append(f'<DataArray type="{kind}" {name}{extra} format="appended" offset="{offset}"/>')
            blobs.append(blob)
            offset += len(blob)
        xml = ('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" '
               'header_type="UInt32">\n<UnstructuredGrid><Piece NumberOfPoints="4" NumberOfCells="1">\n'
               f"<Points>{tags[0]}</Points>\n<Cells>{tags[1]}{tags[2]}{tags[3]}</Cells>\n"
               f"<CellData>{tags[4]}</CellData>\n</Piece></UnstructuredGrid>\n"
               f'<AppendedData encoding="{encoding}">\n_').encode() + b"".join(blobs) + b"\n</AppendedData></VTKFile>\n"
        path = os.path.join(t, f"appended_{encoding}.vtu")
        open(path, "wb").write(xml)
        rc, j, err = check_json(path)
        check(f"vtu appended {encoding}", rc == 0 and j["elements"] == {"tet": 1} and j["groups"] ==
              [{"name": "part=7", "elements": {"tet": 1}}] and abs(j["quality"]["tet_mean_ratio"]["min"] - 0.8399) < 1e-3,
              f"exit {rc} {err} {j}")

    # Deliberately broken: one tetrahedron with two corners swapped; one triangle flipped.
    lines = open(os.path.join(t, "g22.msh")).read().splitlines()
    start = lines.index("$Elements") + 2
    for k in range(start, len(lines)):
        f = lines[k].split()
        if f[1] == "4":  # the first linear tetrahedron
            n = 3 + int(f[2])
            f[n], f[n + 1] = f[n + 1], f[n]
            lines[k] = " ".join(f)
            break
    bad = os.path.join(t, "inverted.msh")
    open(bad, "w").write("\n".join(lines) + "\n")
    rc, j, _ = check_json(bad)
    check("inverted tet", rc == 3 and j and j["inverted"] == 1 and not j["valid"], f"exit {rc} {j and j['problems']}")
    rc, out, _ = run("check", bad)
    check("inverted tet text", rc == 3 and "INVALID" in out, out[-300:])

    stl = open(os.path.join(t, "s.obj")).read().splitlines()
    for k, line in enumerate(stl):
        if line.startswith("f "):
            f = line.split()
            stl[k] = " ".join([f[0], f[1], f[3], f[2]])
            break
    flipped = os.path.join(t, "flipped.obj")
    open(flipped, "w").write("\n".join(stl) + "\n")
    rc, j, _ = check_json(flipped)
    check("flipped triangle", rc == 3 and j and j["surface"]["misoriented_edges"] == 3, f"exit {rc} {j and j['surface']}")

    # Unreadable: exit 2, one line naming the file, nothing on stdout.
    raw = open(os.path.join(t, "g41b.msh"), "rb").read()
    bad_files = {"garbage.msh": b"this is not a mesh\x00\x01\x02", "garbage.vtu": b"<html></html>",
                 "garbage.inp": b"1, 2, 3\n", "garbage.stl": b"\x00" * 10, "empty.obj": b"",
                 "truncated.msh": raw[: len(raw) // 2], "unknown.xyz": b"1 2 3"}
    for name, data in bad_files.items():
        path = os.path.join(t, name)
        open(path, "wb").write(data)
        rc, out, err = run("check", path)
        lines = err.strip().splitlines()
        check(f"bad {name}", rc == 2 and len(lines) == 1 and name in lines[0] and out == "", f"exit {rc} {err!r}")
    rc, out, err = run("check", os.path.join(t, "missing.msh"))
    check("missing file", rc == 2 and "missing.msh" in err, f"exit {rc} {err!r}")

print(f"check: {checks - len(failures)} passed, {len(failures)} failed")
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
