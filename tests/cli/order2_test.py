"""--order 2 through the CLI on the OCCT cylinder (r = 1, length 10, along z): every mid-edge
node of the surface mesh lies on the CAD surface (r = 1 or a cap) within 1e-6 of the model
size, mid nodes are shared (one per mesh edge), no Jacobian is non-positive at the corners and
centroids, the report counts the mid nodes, and `anisomesh check` finds the file valid. With
the volume mesher in the build (--dim 3 exits 0), the tetrahedra share the triangles' mid
nodes and their boundary mid nodes are on the CAD surface unless the report says elements
were left straight.

usage: order2_test.py ANISOMESH SHARED_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

import meshio
import numpy as np

CLI, SHARED = sys.argv[1], sys.argv[2]
MODEL = os.path.join(SHARED, "bench", "cylinder_r1_l10.step")
TOL = 1e-6 * np.sqrt(2 * 2 + 2 * 2 + 10 * 10)
failures, checks = [], 0


def check(name, ok, detail=""):
    global checks
    checks += 1
    if not ok:
        failures.append(f"{name}: {detail}")


def on_cad(x):
    r = np.hypot(x[:, 0], x[:, 1])
    return (np.abs(r - 1) < TOL) | (np.abs(x[:, 2]) < TOL) | (np.abs(x[:, 2] - 10) < TOL)


def tri6_min_ratio(P, T):
    """Smallest Jacobian (along the corners' normal) at corners and centroid over the straight one."""
    c, m = P[T[:, :3]], P[T[:, 3:]]
    n = np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0])
    area2 = np.linalg.norm(n, axis=1)
    n /= area2[:, None]
    worst = np.inf
    for L in ([1, 0, 0], [0, 1, 0], [0, 0, 1], [1 / 3, 1 / 3, 1 / 3]):
        g = [c[:, i] * (4 * L[i] - 1) for i in range(3)]
        for k, (i, j) in enumerate(((0, 1), (1, 2), (2, 0))):
            g[i] = g[i] + 4 * L[j] * m[:, k]
            g[j] = g[j] + 4 * L[i] * m[:, k]
        det = np.einsum("ij,ij->i", n, np.cross(g[1] - g[0], g[2] - g[0]))
        worst = min(worst, (det / area2).min())
    return worst


with tempfile.TemporaryDirectory() as t:
    out, report = os.path.join(t, "s.msh"), os.path.join(t, "s.json")
    p = subprocess.run([CLI, "mesh", MODEL, "-o", out, "--dim", "2", "--order", "2", "--hmax", "0.5", "-q",
                        "--report", report], capture_output=True, text=True)
    check("mesh --dim 2 --order 2", p.returncode == 0, p.stderr)
    if p.returncode == 0:
        r = json.load(open(report))
        m = meshio.read(out)
        P = m.points
        T = np.vstack([b.data for b in m.cells if b.type == "triangle6"])
        mids = np.unique(T[:, 3:])
        check("report order2", r["order2"]["straightened"] == 0 and r["order2"]["mid_nodes"] == len(mids), str(r["order2"]))
        edges = {tuple(sorted(e)) for tri in T[:, :3] for e in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0]))}
        check("one mid node per edge", len(mids) == len(edges), f"{len(mids)} mid nodes, {len(edges)} edges")
        off = ~on_cad(P[mids])
        check("mid nodes on the CAD surface", not off.any(), f"{int(off.sum())} of {len(mids)} off")
        check("positive Jacobians", tri6_min_ratio(P, T) > 0, f"{tri6_min_ratio(P, T)}")
        c = subprocess.run([CLI, "check", out, "--json"], capture_output=True, text=True)
        j = json.loads(c.stdout) if c.returncode in (0, 3) else None
        check("check valid", c.returncode == 0 and j and j["elements"] == {"triangle6": len(T)}, c.stdout[:300])

    out3, report3 = os.path.join(t, "v.msh"), os.path.join(t, "v.json")
    p = subprocess.run([CLI, "mesh", MODEL, "-o", out3, "--dim", "3", "--order", "2", "--hmax", "0.5", "-q",
                        "--report", report3], capture_output=True, text=True)
    if p.returncode == 0:  # the volume mesher is in this build
        r = json.load(open(report3))
        m = meshio.read(out3)
        P = m.points
        T = np.vstack([b.data for b in m.cells if b.type == "tetra10"])
        S = np.vstack([b.data for b in m.cells if b.type == "triangle6"])
        # meshio's tetra10: 4:(0,1) 5:(1,2) 6:(2,0) 7:(0,3) 8:(1,3) 9:(2,3)
        tet_mid = {}
        for a, b, k in ((0, 1, 4), (1, 2, 5), (2, 0, 6), (0, 3, 7), (1, 3, 8), (2, 3, 9)):
            for row in T[:, [a, b, k]]:
                tet_mid.setdefault((min(row[0], row[1]), max(row[0], row[1])), set()).add(row[2])
        shared = all(tet_mid.get((min(tri[i], tri[j]), max(tri[i], tri[j]))) == {tri[k]}
                     for tri in S for i, j, k in ((0, 1, 3), (1, 2, 4), (2, 0, 5)))
        check("tet10 shares the triangles' mid nodes", shared)
        off = int((~on_cad(P[np.unique(S[:, 3:])])).sum())
        check("boundary mid nodes on the CAD surface unless straightened", off == 0 or r["order2"]["straightened"] > 0,
              f"{off} off, report {r['order2']}")

print(f"order2: {checks - len(failures)} passed, {len(failures)} failed")
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
