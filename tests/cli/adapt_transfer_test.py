#!/usr/bin/env python3
"""anisomesh adapt --transfer (issue 19): the field named by --field, all its components, is
interpolated to the new nodes and written into the output as node data of the same name.

The field is a linear vector v = (1 + 2x - 3y + z, x + y + 2, 0.5 z - x) (its magnitude, which
is not linear, drives the metric), so the P1 transfer reproduces it:
  - 2D, the unit square (flat boundary: every new node lies in the old mesh): every node
    within 1e-9 (relative to max |v|), in .msh (ASCII and binary) and .vtu;
  - 3D, models/cylinder.step (r 10) from a coarse first mesh: nodes farther than the old
    facets' chordal gap from the curved surface within 1e-9; the nodes on it (outside the old
    facets) within |grad v| times that gap, the gap measured here on the old boundary
    triangles (a lattice on each); the report counts them and its largest distance is
    within the gap too.
  - an output format without node data (.inp) exits 2 naming it, no file.
usage: adapt_transfer_test.py CLI MODELS_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

import meshio
import numpy as np

cli, models = sys.argv[1], sys.argv[2]
failures = []
GRAD = np.array([[2, -3, 1], [1, 1, 0], [-1, 0, 0.5]])  # rows: grad of each component
EXACT = 1e-9


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(*args):
    return subprocess.run([cli, *args, "-q"], capture_output=True, text=True, timeout=300)


def v(x):
    return x @ GRAD.T + np.array([1, 2, 0])


def write_field(mesh_path, key, out, scale=1.0):
    m = meshio.read(mesh_path)
    cells = [b for b in m.cells if b.type == key]
    x = m.points / scale
    meshio.Mesh(m.points, cells, point_data={"v": v(x)}).write(out, file_format="gmsh", binary=True)
    return m


def report(path):
    with open(path) as fp:
        r = json.load(fp)
    return r.get("extra", r)["adapt"]


def transferred(path, scale=1.0):
    m = meshio.read(path)
    got = np.asarray(m.point_data.get("v", np.zeros((0, 3))))
    return m.points, got, v(m.points / scale)


with tempfile.TemporaryDirectory() as t:
    j = lambda name: os.path.join(t, name)
    with open(j("sq.json"), "w") as f:
        f.write('{"name": "SQ", "surface": {"type": "plane"}, "domain": {"u": [0, 1], "v": [0, 1]}}')
    r = run("mesh", j("sq.json"), "-o", j("first.msh"), "--dim", "2", "--size", "0.05")
    check(r.returncode == 0, "first mesh of the square " + r.stderr.strip()[-200:])
    write_field(j("first.msh"), "triangle", j("f.msh"))
    for out, extra in [("a.msh", []), ("b.msh", ["--binary"]), ("a.vtu", []), ("b.vtu", ["--binary"])]:
        r = run("adapt", j("sq.json"), "--from", j("f.msh"), "--field", "v", "-o", j(out), "--target-nodes", "800",
                "--transfer", "--report", j(out + ".json"), *extra)
        check(r.returncode == 0, f"square --transfer -o {out} {' '.join(extra)}: " + r.stderr.strip()[-200:])
        if r.returncode != 0:
            continue
        P, got, want = transferred(j(out))
        scale = np.abs(want).max()
        err = np.abs(got - want).max() / scale if got.shape == want.shape else np.inf
        check(err < EXACT, f"square {out}: {len(P)} nodes, {got.shape[1] if got.ndim == 2 else 0} components, "
                           f"largest error {err:.2e} of max |v| (< {EXACT})")
        tr = report(j(out + ".json"))["transfer"]
        check(tr["array"] == "v" and tr["components"] == 3 and tr["max_distance_outside"] < 1e-12,
              f"square {out}: report transfer block {tr}")

    # 3D: a curved boundary
    cyl = os.path.join(models, "cylinder.step")
    r = run("mesh", cyl, "-o", j("c0.msh"), "--size", "5")
    check(r.returncode == 0, "first mesh of the cylinder " + r.stderr.strip()[-200:])
    old = write_field(j("c0.msh"), "tetra", j("c0f.msh"))
    # the old facets' largest gap to the cylinder surface r = 10: a lattice on each boundary triangle
    tris = np.vstack([b.data for b in old.cells if b.type == "triangle"])
    P = old.points[tris]
    lat = np.array([(a / 8, b / 8, 1 - a / 8 - b / 8) for a in range(9) for b in range(9 - a)])
    X = np.einsum("qk,tkd->tqd", lat, P)
    rho = np.hypot(X[..., 0], X[..., 1])
    lateral = np.abs(np.hypot(P[..., 0], P[..., 1]) - 10).max(1) < 1e-6
    gap = float((10 - rho[lateral]).max())
    r = run("adapt", cyl, "--from", j("c0f.msh"), "--field", "v", "-o", j("c1.vtu"), "--target-nodes", "3000",
            "--transfer", "--report", j("c1.json"))
    check(r.returncode == 0, "cylinder --transfer: " + r.stderr.strip()[-200:])
    if r.returncode == 0:
        X1, got, want = transferred(j("c1.vtu"))
        scale = np.abs(want).max()
        rho1 = np.hypot(X1[:, 0], X1[:, 1])
        inside = rho1 < 10 - gap * 1.01
        err = np.abs(got - want).max(1)
        bound = np.linalg.norm(GRAD, axis=1).max() * gap * 1.05
        check(err[inside].max() / scale < EXACT,
              f"cylinder: {inside.sum()} nodes inside the old mesh, largest error {err[inside].max() / scale:.2e} of max |v|")
        check(err[~inside].max() <= bound,
              f"cylinder: {(~inside).sum()} nodes near the curved surface, largest error {err[~inside].max():.3e} "
              f"<= |grad v| x old chordal gap {gap:.4f} = {bound:.3e}")
        tr = report(j("c1.json"))["transfer"]
        check(tr["nodes_outside"] > 0 and tr["max_distance_outside"] <= gap * 1.05,
              f"cylinder: report {tr['nodes_outside']} nodes outside the old mesh, at most "
              f"{tr['max_distance_outside']:.4f} away (gap {gap:.4f})")

    r = run("adapt", j("sq.json"), "--from", j("f.msh"), "--field", "v", "-o", j("x.inp"), "--transfer")
    check(r.returncode == 2 and "x.inp" in r.stderr and not os.path.exists(j("x.inp")),
          f"--transfer to .inp: exit {r.returncode}: {r.stderr.strip()[:200]}")

print("adapt --transfer:", "FAILED " + "; ".join(failures) if failures else "all passed")
sys.exit(1 if failures else 0)
