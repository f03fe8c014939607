#!/usr/bin/python3
"""Surface quality at tiny CAD features and thin faces (issue 4): a measurement, not a test.
usage: tools/bench/surface_small_features.py [CLI] [--models A,B,..] [--volume A,B,..] [--extra "ARGS"]
For each model: `CLI mesh MODEL --dim 2 --hmax-rel 0.02 --curvature-ratio 0.26 --anisotropy 1`
(--extra replaces those options), then the referee's triangle figures (eta min/avg, min angle,
triangles with eta < 0.1) and how many of those bad triangles the CAD geometry forces: a
triangle is "forced" when its smallest angle is at a CAD vertex where the face's corner (the
angles of all the face's triangles at that vertex, summed in 3D) is so sharp that even the
best triangle filling it (isosceles, apex = the corner) has eta < 0.1 (corner < 3.31 deg), or when
its nodes lie on the two CAD edges of such a corner where they are closer than h_min
(1e-4 x diagonal; its height is below that): a wedge the sizes may not resolve.
`free` = bad - forced: the needles the mesher could have avoided.
For the --volume models also the default 3D run (`--dim 3` with the same options): tetrahedra,
eta min/avg and the referee's minimum dihedral angle (issue 5's 2 deg bar)."""
import argparse, contextlib, io, math, os, subprocess, sys, tempfile, time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared"))
if not os.path.isdir(SHARED):
    SHARED = "/work/shared"
sys.path.insert(0, os.path.join(SHARED, "tools"))
import meshq  # noqa: E402

MODELS = "U_Joint_2.stp,part.step,Block.stp,SampleCrankshaft4A.stp,simple_plane.brep,submarine.stp," \
         "wing_fuselage.step,SlenderSurface.brep,component8.step"
VOLUME = "U_Joint_2.stp,part.step,Block.stp"
OPTIONS = "--hmax-rel 0.02 --curvature-ratio 0.26 --anisotropy 1"
ETA_BAD = 0.1


def iso_eta(apex):
    """Mean ratio of the isosceles triangle with apex angle `apex` (the best with that angle)."""
    return 2 * math.sqrt(3) * math.sin(apex) / (2 + 4 * math.sin(apex / 2) ** 2)


def forced_corner():
    lo, hi = 1e-9, math.pi / 3  # iso_eta increases on (0, pi/3]
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if iso_eta(mid) < ETA_BAD else (lo, mid)
    return lo


def triangle_analysis(path):
    """Bad triangles (eta < 0.1) and those forced by a sharp CAD corner."""
    import meshio
    with contextlib.redirect_stdout(io.StringIO()):
        m = meshio.read(path)
    p = np.asarray(m.points, dtype=float)
    dim = m.point_data["gmsh:dim_tags"][:, 0]
    tag = m.point_data["gmsh:dim_tags"][:, 1]
    tris, faces = [], []
    for cb, g in zip(m.cells, m.cell_data["gmsh:geometrical"]):
        if cb.type in ("triangle", "triangle6"):
            tris.append(np.asarray(cb.data)[:, :3])
            faces.append(np.asarray(g))
    t = np.vstack(tris)
    f = np.concatenate(faces)
    x = [p[t[:, k]] for k in range(3)]
    ang = []
    for k in range(3):
        u, v = x[(k + 1) % 3] - x[k], x[(k + 2) % 3] - x[k]
        c = np.einsum("ij,ij->i", u, v) / np.maximum(np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1), 1e-300)
        ang.append(np.arccos(np.clip(c, -1, 1)))
    ang = np.array(ang).T  # angle at corner k of each triangle
    area = 0.5 * np.linalg.norm(np.cross(x[1] - x[0], x[2] - x[0]), axis=1)
    l2 = sum(np.einsum("ij,ij->i", d, d) for d in (x[1] - x[0], x[2] - x[1], x[0] - x[2]))
    eta = 4 * math.sqrt(3) * area / np.maximum(l2, 1e-300)
    # The face's corner angle at each CAD vertex: angles of the face's triangles there, summed.
    corner = {}
    for k in range(3):
        for i in np.where(dim[t[:, k]] == 0)[0]:
            key = (int(t[i, k]), int(f[i]))
            corner[key] = corner.get(key, 0.0) + float(ang[i, k])
    limit = forced_corner()
    sharp = {key for key, a in corner.items() if a < limit}
    # The two CAD edges of each sharp corner (face, edge, edge): the edges of the other two
    # nodes of the face's triangles at that vertex.
    wedges = set()
    for k in range(3):
        for i in np.where(dim[t[:, k]] == 0)[0]:
            if (int(t[i, k]), int(f[i])) not in sharp:
                continue
            tags = sorted({int(tag[t[i, j]]) for j in range(3) if j != k and dim[t[i, j]] == 1})
            if len(tags) == 2:
                wedges.add((int(f[i]), tags[0], tags[1]))
    hmin = 1e-4 * float(np.linalg.norm(p.max(axis=0) - p.min(axis=0)))
    longest = np.sqrt(np.maximum.reduce([np.einsum("ij,ij->i", d, d) for d in (x[1] - x[0], x[2] - x[1], x[0] - x[2])]))
    height = 2 * area / np.maximum(longest, 1e-300)
    bad = np.where(eta < ETA_BAD)[0]
    forced = 0
    for i in bad:
        k = int(np.argmin(ang[i]))
        n = int(t[i, k])
        if dim[n] == 0 and corner.get((n, int(f[i])), math.pi) < limit:
            forced += 1
            continue
        # Squeezed between the two edges of a sharp corner, where they are closer than h_min.
        if (dim[t[i]] > 1).any() or height[i] >= hmin:
            continue
        tags = sorted({int(tag[v]) for v in t[i] if dim[v] == 1})
        if len(tags) == 2 and (int(f[i]), tags[0], tags[1]) in wedges:
            forced += 1
    return len(bad), forced


def run(cmd, timeout=900):
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
        return p.returncode, time.perf_counter() - t0, (p.stderr.strip().splitlines() or [""])[-1][:80]
    except subprocess.TimeoutExpired:
        return "timeout", time.perf_counter() - t0, "timeout"


def mesh(cli, path, dim, extra, out):
    """Meshes; returns (referee stats or None, seconds, why)."""
    if os.path.exists(out):
        os.remove(out)
    rc, dt, why = run([cli, "mesh", path, "-o", out, "--dim", str(dim)] + extra.split())
    if rc != 0 or not os.path.exists(out):
        return None, dt, f"failed ({rc}): {why}"
    with contextlib.redirect_stdout(io.StringIO()):
        return meshq.stats(out), dt, ""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("cli", nargs="?", default=os.path.join(HERE, "..", "..", "build", "anisomesh"))
    ap.add_argument("--models", default=MODELS)
    ap.add_argument("--volume", default=VOLUME, help="models also meshed in 3D ('' for none)")
    ap.add_argument("--extra", default=OPTIONS)
    ap.add_argument("--dir", default=os.path.join(SHARED, "models"))
    a = ap.parse_args()
    tmp = tempfile.mkdtemp()
    out = os.path.join(tmp, "out.msh")
    print(f"surface: {a.extra} --dim 2;  forced = needles at CAD corners < {math.degrees(forced_corner()):.2f} deg")
    print(f"{'model':26s} {'tris':>8s} {'eta_min':>8s} {'eta_avg':>8s} {'ang_min':>8s} {'eta<0.1':>8s} "
          f"{'forced':>7s} {'free':>6s} {'time_s':>7s}")
    for name in a.models.split(","):
        q, dt, why = mesh(a.cli, os.path.join(a.dir, name), 2, a.extra, out)
        if not q:
            print(f"{name:26s} {why}")
            continue
        bad, forced = triangle_analysis(out)
        print(f"{name:26s} {q['tris']:8d} {q['tri_eta_min']:8.4f} {q['tri_eta_avg']:8.4f} {q['tri_angle_min']:8.2f} "
              f"{bad:8d} {forced:7d} {bad - forced:6d} {dt:7.1f}")
    if not a.volume:
        return
    print(f"\nvolume: {a.extra} --dim 3")
    print(f"{'model':26s} {'tets':>8s} {'eta_min':>8s} {'eta_avg':>8s} {'dih_min':>8s} {'time_s':>7s}")
    for name in a.volume.split(","):
        q, dt, why = mesh(a.cli, os.path.join(a.dir, name), 3, a.extra, out)
        if not q:
            print(f"{name:26s} {why}")
            continue
        print(f"{name:26s} {q.get('tets', 0):8d} {q.get('eta_min', 0):8.4f} {q.get('eta_avg', 0):8.4f} "
              f"{q.get('dihedral_min', 0):8.2f} {dt:7.1f}")


if __name__ == "__main__":
    main()
