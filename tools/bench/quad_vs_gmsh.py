#!/usr/bin/python3
"""Quad meshes side by side with Gmsh's Blossom recombination (issue 7).
usage: tools/bench/quad_vs_gmsh.py [CLI] [--dir MODELS] [--only a.step,b.brep] [--no-gmsh | --gmsh-only]
                                  [--gmsh-cache FILE.json] [--ours-cache FILE.json] [--timeout S]
                                  [--quad-method merge|morph|mixed]
For every model of MODELS/MANIFEST.json: `anisomesh mesh --dim 2 --quad --hmax-rel 0.02
--curvature-ratio 0.26 --anisotropy 1` and Gmsh 4.8 (`-2 -algo front2d`, Mesh.RecombineAll=1,
Blossom, the same relative size and curvature sizing as shared/tools/gmsh_anchor.py), each
measured the same way as shared/tools/check_quad.py: quad fraction, scaled Jacobian min/avg
(3D, per quad the minimum over its corners), open edges, area against the manifest; and the
mean scaled Jacobian of the quads adjacent to the boundary (a corner on a CAD edge or vertex:
the node's entity dimension ≤ 1 in the MSH), the elements the boundary postprocessing of
thesis 4.8.3 takes care of.
Prints one table row per model, then the means. --gmsh-cache keeps Gmsh's figures per model in
FILE.json (read when present, written after each Gmsh run): Gmsh's side does not change between
runs of ours (--ours-cache does the same for ours, e.g. to print the table of two separate
runs; keep one file per --quad-method). The last line compares the means over the models both
mesh (Gmsh with at least one quad). Needs Debian's python3-gmsh/meshio/numpy."""
import json, os, subprocess, sys, tempfile
import numpy as np, meshio

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.abspath(os.path.join(here, "..", ".."))
args = sys.argv[1:]
cli = args[0] if args and not args[0].startswith("--") else os.path.join(root, "build", "anisomesh")
opt = lambda k, d: args[args.index(k) + 1] if k in args else d
d = opt("--dir", os.path.abspath(os.path.join(root, "..", "shared", "models")))
only = opt("--only", "")
timeout = int(opt("--timeout", "600"))
method = opt("--quad-method", "merge")
man = [m for m in json.load(open(os.path.join(d, "MANIFEST.json"))) if "error" not in m]
if only: man = [m for m in man if m["file"] in only.split(",")]
tmp = tempfile.mkdtemp()
cache_file = opt("--gmsh-cache", "")
cache = json.load(open(cache_file)) if cache_file and os.path.exists(cache_file) else {}
ours_file = opt("--ours-cache", "")
ours_cache = json.load(open(ours_file)) if ours_file and os.path.exists(ours_file) else {}

GMSH = r'''
import sys, gmsh
f, out = sys.argv[1], sys.argv[2]
gmsh.initialize(); gmsh.option.setNumber("General.Terminal", 0)
gmsh.option.setNumber("Mesh.Algorithm", 6)          # front2d
gmsh.option.setNumber("Mesh.RecombineAll", 1)       # Blossom recombination
gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 24)
gmsh.model.occ.importShapes(f); gmsh.model.occ.synchronize()
x0, y0, z0, x1, y1, z1 = gmsh.model.getBoundingBox(-1, -1)
gmsh.option.setNumber("Mesh.MeshSizeMax", 0.02 * ((x1-x0)**2 + (y1-y0)**2 + (z1-z0)**2) ** 0.5)
gmsh.model.mesh.generate(2); gmsh.write(out); gmsh.finalize()
'''

def measure(path, m):
    M = meshio.read(path); P = np.asarray(M.points, float)
    Q = [np.asarray(c.data) for c in M.cells if c.type == "quad"]; T = [np.asarray(c.data) for c in M.cells if c.type == "triangle"]
    Q = np.vstack(Q) if Q else np.zeros((0, 4), int); T = np.vstack(T) if T else np.zeros((0, 3), int)
    nq, nt = len(Q), len(T)
    tri = np.vstack([T, Q[:, [0, 1, 2]], Q[:, [0, 2, 3]]]) if nq else T
    area = 0.5 * np.linalg.norm(np.cross(P[tri[:, 1]] - P[tri[:, 0]], P[tri[:, 2]] - P[tri[:, 0]]), axis=1).sum()
    E = np.vstack([T[:, [0, 1]], T[:, [1, 2]], T[:, [2, 0]], Q[:, [0, 1]], Q[:, [1, 2]], Q[:, [2, 3]], Q[:, [3, 0]]])
    _, cnt = np.unique(np.sort(E, axis=1), axis=0, return_counts=True)
    sj = np.ones(nq)
    for k in range(4):
        o, u, v = P[Q[:, k]], P[Q[:, (k + 1) % 4]], P[Q[:, (k + 3) % 4]]
        e1, e2 = u - o, v - o
        s = np.linalg.norm(np.cross(e1, e2), axis=1) / np.maximum(np.linalg.norm(e1, axis=1) * np.linalg.norm(e2, axis=1), 1e-300)
        sj = np.minimum(sj, s)
    dims = M.point_data.get("gmsh:dim_tags")
    near = (dims[Q, 0] <= 1).any(axis=1) if dims is not None and nq else np.zeros(nq, bool)
    return {"bsj_avg": float(sj[near].mean()) if near.any() else float("nan"),"quads": nq, "tris": nt, "frac": nq / max(nq + nt, 1), "sj_min": float(sj.min()) if nq else 0.0,
            "sj_avg": float(sj.mean()) if nq else 0.0, "open": int((cnt == 1).sum()), "area_rel": (area - m["area"]) / m["area"]}

def run(cmd, out, m):
    if os.path.exists(out): os.remove(out)
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, "timeout"
    if p.returncode != 0 or not os.path.exists(out):
        return None, f"exit {p.returncode}"
    return measure(out, m), ""

def cell(r, why):
    if r is None: return f"{why:>45}"
    return (f"{100 * r['frac']:6.1f} {r['sj_min']:6.3f} {r['sj_avg']:6.3f} {r.get('bsj_avg', float('nan')):6.3f} "
            f"{r['open']:5d} {100 * r['area_rel']:+7.2f}%")

print(f"{'model':<36} {'anisomesh: quad%  SJmin  SJavg  bSJavg  open   area':>47} | {'gmsh blossom: quad%  SJmin  SJavg  bSJavg  open   area':>51}")
ours, theirs, both = [], [], []
for m in man:
    f = os.path.join(d, m["file"])
    if "--gmsh-only" in args: a, wa = None, "skipped"
    elif m["file"] in ours_cache: a, wa = ours_cache[m["file"]]
    else:
        a, wa = run([cli, "mesh", f, "-o", f"{tmp}/a.msh", "--dim", "2", "--quad", "--hmax-rel", "0.02",
                     "--curvature-ratio", "0.26", "--anisotropy", "1", "--quad-method", method], f"{tmp}/a.msh", m)
        if ours_file:
            ours_cache[m["file"]] = [a, wa]
            json.dump(ours_cache, open(ours_file, "w"))
    if "--no-gmsh" in args: g, wg = None, "skipped"
    elif m["file"] in cache: g, wg = cache[m["file"]]
    else:
        g, wg = run(["/usr/bin/python3", "-c", GMSH, f, f"{tmp}/g.msh"], f"{tmp}/g.msh", m)
        if cache_file:
            cache[m["file"]] = [g, wg]
            json.dump(cache, open(cache_file, "w"))
    if a: ours.append(a)
    if g: theirs.append(g)
    if a and g and g["quads"] > 0: both.append((a, g))  # a Gmsh mesh without quads is no recombination
    print(f"{m['file']:<36} {cell(a, wa):>47} | {cell(g, wg):>51}", flush=True)
mean = lambda rows, k: np.nanmean([r.get(k, np.nan) for r in rows]) if rows else float("nan")
print(f"{'mean (meshed models)':<36} {100 * mean(ours, 'frac'):6.1f} {min([r['sj_min'] for r in ours] or [0]):6.3f} {mean(ours, 'sj_avg'):6.3f} {mean(ours, 'bsj_avg'):6.3f}"
      f"{'':>16} | {100 * mean(theirs, 'frac'):6.1f} {min([r['sj_min'] for r in theirs] or [0]):6.3f} {mean(theirs, 'sj_avg'):6.3f} "
      f"{mean(theirs, 'bsj_avg'):6.3f}")
print(f"{'mean (models both mesh: ' + str(len(both)) + ')':<36} {100 * mean([a for a, _ in both], 'frac'):6.1f} "
      f"{min([a['sj_min'] for a, _ in both] or [0]):6.3f} {mean([a for a, _ in both], 'sj_avg'):6.3f} "
      f"{mean([a for a, _ in both], 'bsj_avg'):6.3f}{'':>16} | "
      f"{100 * mean([g for _, g in both], 'frac'):6.1f} {min([g['sj_min'] for _, g in both] or [0]):6.3f} "
      f"{mean([g for _, g in both], 'sj_avg'):6.3f} {mean([g for _, g in both], 'bsj_avg'):6.3f}   (--quad-method {method})")
