#!/usr/bin/python3
"""Surface meshing speed and memory, side by side with Gmsh 4.8 in the same run (issue 4 §2).
usage: tools/bench/surface_speed.py [CLI] [--runs N]
Whole process, one thread each, same uniform size; prints a table (speedlib.py): wall time
(median), peak memory (max RSS), triangles, bytes per triangle ("net": minus the same
command's footprint at a coarse size, i.e. what the mesh itself costs at peak), triangles
per second and the referee's mean ratio. Cases: the planar 2x1 face at size 0.004 (Gmsh
-algo front2d), and the thesis' AN1 (anisotropic analytic metric; anisomesh only: Gmsh
has no analytic anisotropic sizing)."""
import os, sys, tempfile

from speedlib import cli_and_runs, measure, print_table, shared

cli, runs = cli_and_runs(sys.argv)
t = tempfile.mkdtemp()
rect = os.path.join(shared, "bench", "rect_2x1.step")
an1 = os.path.join(shared, "bench", "AN1.json")


def ours(size):
    return [cli, "mesh", rect, "-o", f"{t}/a.msh", "--dim", "2", "--size", size, "--threads", "1"]


def gmsh(size):
    return ["gmsh", rect, "-2", "-clmin", size, "-clmax", size, "-algo", "front2d", "-nt", "1", "-v", "0", "-format",
            "msh41", "-o", f"{t}/g.msh"]


print_table([
    ("rect 2x1 h=0.004", "anisomesh", measure(ours("0.004"), f"{t}/a.msh", runs, "tris", ours("0.5"))),
    ("rect 2x1 h=0.004", "gmsh front2d", measure(gmsh("0.004"), f"{t}/g.msh", runs, "tris", gmsh("0.5"))),
    ("AN1 (k=1)", "anisomesh", measure([cli, "mesh", an1, "-o", f"{t}/n.msh", "--dim", "2", "--threads", "1"],
                                       f"{t}/n.msh", runs, "tris")),
], "tris")
