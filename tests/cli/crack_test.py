#!/usr/bin/python3
"""Faces inside a solid (issue 20, embedded faces and cracks). models/crack.brep: a 10 mm cube
with the square x, y in [2, 8] at z = 5 inside it (area 36), kept by the CAD as an INTERNAL face
in a shell of its own; models/crack_edge.brep: the square x, y in [0, 5] reaching two sides
of the cube (area 25), imprinted on them.
- default (--internal-faces auto: a shell of only internal faces is a crack): exit 0, status
  ok, the referee finds the mesh valid; volume 1000 (1e-6); the faces used by one tetrahedron
  have area 600 + 2 x the crack's (its two sides are apart); the report counts the crack and
  its duplicated nodes, which are exactly the coincident node pairs of the mesh; every
  duplicated node lies on the crack, none on its front (the crack closes there).
- --internal-faces bond: one-sided: exposed area 600, no coincident nodes, and the crack's
  area is covered by faces of the tetrahedra (conformal: the face is in the volume mesh).
- the edge crack's mouth edges are INTERNAL edges of the cube's faces (slits, Loop::slit):
  meshed into those faces, so the crack opens there too.
- --dim 2: the crack face is meshed with the cube's six.
- the crack stored as an open shell of a FORWARD face (not INTERNAL) is found a sheet and
  meshed as the same crack.
usage: crack_test.py CLI MODELS_DIR SHARED_DIR"""
import json, os, subprocess, sys, tempfile
import functools

import clitest
from clitest import check, failures as fails

import meshio
import numpy as np

cli, models, shared = sys.argv[1], sys.argv[2], sys.argv[3]
t = tempfile.mkdtemp()
run = functools.partial(clitest.run, cli)


def tets_of(path):
    m = meshio.read(path)
    P = np.asarray(m.points, float)
    T = np.vstack([np.asarray(cb.data) for cb in m.cells if cb.type == "tetra"])
    return P, T


def faces(T):
    F = np.sort(np.vstack([T[:, [1, 2, 3]], T[:, [0, 2, 3]], T[:, [0, 1, 3]], T[:, [0, 1, 2]]]), axis=1)
    return np.unique(F, axis=0, return_counts=True)


def area(P, F):
    return float(0.5 * np.linalg.norm(np.cross(P[F[:, 1]] - P[F[:, 0]], P[F[:, 2]] - P[F[:, 0]]), axis=1).sum())


def volume(P, T):
    a, b, c, d = (P[T[:, k]] for k in range(4))
    return float(np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a).sum() / 6)


def coincident(P):
    """Groups of nodes at the same position (exactly: copies are bit-identical)."""
    _, inverse, counts = np.unique(P, axis=0, return_inverse=True, return_counts=True)
    return [np.flatnonzero(inverse == g) for g in np.flatnonzero(counts > 1)]


def on_plane(P, F, lo, hi):
    """Faces with all three nodes on z = 5 inside the square [lo, hi]^2."""
    X = P[F]
    return F[np.all(np.abs(X[:, :, 2] - 5) < 1e-9, axis=1) & np.all((X[:, :, :2] >= lo - 1e-9) & (X[:, :, :2] <= hi + 1e-9), axis=(1, 2))]


for name, lo, hi, crack_area in (("crack", 2, 8, 36.0), ("crack_edge", 0, 5, 25.0)):
    model = os.path.join(models, name + ".brep")
    out, rep = os.path.join(t, name + ".msh"), os.path.join(t, name + ".json")
    p = run("mesh", model, "-o", out, "--report", rep, "--hmax", "1.5")
    check(p.returncode == 0, f"{name}: exit 0 ({p.returncode}: {p.stderr.strip()[-300:]})")
    if p.returncode != 0: continue
    r = json.load(open(rep))
    check(r["status"] == "ok", f"{name}: status ok ({r['status']}: {r.get('problems')})")
    cr = r.get("cracks", {})
    check(cr.get("faces") == 1 and cr.get("nodes_duplicated", 0) > 0, f"{name}: report counts one crack ({cr})")
    P, T = tets_of(out)
    u, cnt = faces(T)
    check(abs(volume(P, T) - 1000) < 1e-6 * 1000, f"{name}: volume {volume(P, T):.6f} = 1000")
    ex = area(P, u[cnt == 1])
    check(abs(ex - (600 + 2 * crack_area)) < 1e-6 * 600, f"{name}: exposed area {ex:.6f} = 600 + 2 x {crack_area} (two-sided)")
    groups = coincident(P)
    check(len(groups) == cr.get("nodes_duplicated"), f"{name}: {len(groups)} coincident node groups = duplicated nodes")
    front = [g for g in groups if not (abs(P[g[0], 2] - 5) < 1e-9 and np.all((P[g[0], :2] >= lo - 1e-9) & (P[g[0], :2] <= hi + 1e-9)))]
    check(not front, f"{name}: every duplicated node on the crack ({len(front)} elsewhere)")
    edges = [hi] + ([lo] if lo > 0 else [])  # the front: the crack's sides inside the cube
    tip = [g for g in groups if any(abs(P[g[0], k] - e) < 1e-9 for k in (0, 1) for e in edges)]
    check(not tip, f"{name}: no duplicated node on the crack front ({len(tip)})")
    ref = subprocess.run(["/usr/bin/python3", os.path.join(shared, "tools", "meshq.py"), out], capture_output=True, text=True)
    check(ref.returncode == 0, f"{name}: the referee accepts the mesh ({ref.stdout.strip()[-300:]})")
    q = json.loads(ref.stdout.strip().splitlines()[-1]) if ref.returncode == 0 else {}
    check(q.get("edges_open") == 0 and q.get("edges_nonmanifold") == 0 and abs(q.get("tri_area", 0) - (600 + 2 * crack_area)) < 1e-6 * 600,
          f"{name}: the boundary triangles close, no non-manifold edge, area 600 + 2 x {crack_area} ({q.get('edges_open')}, {q.get('edges_nonmanifold')}, {q.get('tri_area')})")

    # bonded: one-sided, conformal
    outb = os.path.join(t, name + "_bond.msh")
    p = run("mesh", model, "-o", outb, "--hmax", "1.5", "--internal-faces", "bond")
    check(p.returncode == 0, f"{name} bond: exit 0 ({p.stderr.strip()[-300:]})")
    if p.returncode == 0:
        P, T = tets_of(outb)
        u, cnt = faces(T)
        check(abs(area(P, u[cnt == 1]) - 600) < 1e-6 * 600, f"{name} bond: exposed area {area(P, u[cnt == 1]):.6f} = 600")
        check(not coincident(P), f"{name} bond: no coincident nodes")
        inner = on_plane(P, u[cnt == 2], lo, hi)
        check(abs(area(P, inner) - crack_area) < 1e-6 * crack_area,
              f"{name} bond: tetrahedron faces cover the crack ({area(P, inner):.6f} of {crack_area})")

    out2 = os.path.join(t, name + "_2d.msh")
    p = run("mesh", model, "-o", out2, "--dim", "2", "--hmax", "1.5")
    check(p.returncode == 0, f"{name} 2D: exit 0 ({p.stderr.strip()[-300:]})")

# The same crack stored as an open shell of a FORWARD face (a "second, non-manifold shell",
# as other writers keep it; ShapeFix drops such a shell): detected as a sheet, meshed as a crack.
text = open(os.path.join(models, "crack.brep")).read().splitlines()
internal = [i for i, l in enumerate(text) if l == "i3 0 *"]
check(len(internal) == 1, "crack.brep holds its face INTERNAL in a shell of its own (i3)")
if len(internal) == 1:
    text[internal[0]] = "+3 0 *"
    sheet = os.path.join(t, "crack_sheet.brep")
    open(sheet, "w").write("\n".join(text) + "\n")
    out, rep = os.path.join(t, "sheet.msh"), os.path.join(t, "sheet.json")
    p = run("mesh", sheet, "-o", out, "--report", rep, "--hmax", "1.5")
    check(p.returncode == 0, f"sheet shell: exit 0 ({p.stderr.strip()[-300:]})")
    if p.returncode == 0:
        P, T = tets_of(out)
        u, cnt = faces(T)
        check(json.load(open(rep)).get("cracks", {}).get("faces") == 1, "sheet shell: meshed as a crack")
        check(abs(area(P, u[cnt == 1]) - 672) < 1e-6 * 600, f"sheet shell: exposed area {area(P, u[cnt == 1]):.6f} = 672")

print("FAILED: " + "; ".join(fails) if fails else "all passed")
sys.exit(1 if fails else 0)
