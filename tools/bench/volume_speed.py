#!/usr/bin/python3
"""Volume meshing speed and memory, side by side with Gmsh 4.8 in the same run (issue 5 §2).
usage: tools/bench/volume_speed.py [CLI] [--runs N]
Whole process, one thread each, same uniform size; the table of speedlib.py (tetrahedra,
bytes per tetrahedron, tetrahedra per second, the referee's mean ratio and smallest
dihedral angle). Cases: the unit cube at size 0.02 against Gmsh's HXT (its fastest 3D
mesher, -algo hxt), and CAD models at 2 % of their diagonal against Gmsh's default
Delaunay. Then the cube with two threads each (ours: the smoothing inside the solid; the
same mesh as with one; HXT: its parallel Delaunay)."""
import json, os, subprocess, sys, tempfile

from speedlib import cli_and_runs, measure, print_table, root, shared

cli, runs = cli_and_runs(sys.argv)
t = tempfile.mkdtemp()


def ours(model, size, threads=1):
    return [cli, "mesh", model, "-o", f"{t}/a.msh", "--dim", "3", "--size", str(size), "--threads", str(threads)]


def gmsh(model, size, algo, threads=1):
    return ["gmsh", model, "-3", "-clmin", str(size), "-clmax", str(size), "-algo", algo, "-nt", str(threads), "-v",
            "0", "-format", "msh41", "-o", f"{t}/g.msh"]


def diagonal(model):
    p = subprocess.run([cli, "info", "--json", model], capture_output=True, text=True)
    return json.loads(p.stdout)["bbox"]["diagonal"] if p.returncode == 0 else None


cube = os.path.join(shared, "bench", "cube_1.step")
rows = [("cube h=0.02", "anisomesh", measure(ours(cube, 0.02), f"{t}/a.msh", runs, "tets", ours(cube, 0.5))),
        ("cube h=0.02", "gmsh hxt", measure(gmsh(cube, 0.02, "hxt"), f"{t}/g.msh", runs, "tets", gmsh(cube, 0.5, "hxt")))]
for name in ("models/bracket.step", "../shared/models/part.step", "../shared/models/cylinder2.brep"):
    model = os.path.normpath(os.path.join(root, name))
    d = diagonal(model)
    if not d:
        continue
    h = round(0.02 * d, 6)
    label = f"{os.path.basename(model)} h={h:g}"
    rows.append((label, "anisomesh", measure(ours(model, h), f"{t}/a.msh", runs, "tets")))
    rows.append((label, "gmsh delaunay", measure(gmsh(model, h, "del3d"), f"{t}/g.msh", runs, "tets")))
rows.append(("cube h=0.02, 2 threads", "anisomesh",
             measure(ours(cube, 0.02, 2), f"{t}/a.msh", runs, "tets", ours(cube, 0.5, 2))))
rows.append(("cube h=0.02, 2 threads", "gmsh hxt",
             measure(gmsh(cube, 0.02, "hxt", 2), f"{t}/g.msh", runs, "tets", gmsh(cube, 0.5, "hxt", 2))))
print_table(rows, "tets")
