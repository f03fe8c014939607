#!/usr/bin/python3
"""--quad surface meshes (issue 7): mostly quads, none inverted (scaled Jacobian >= 0.1 at every
corner, measured in 3D from the written file as shared/tools/check_quad.py does), closed where the
model is closed, area within 1% of the CAD area of the distinct faces, the report's quad block
agreeing with the file (counts, fraction, scaled Jacobian, and the boundary layer's: the quads with
a node on a model edge or vertex, the node's entity dimension <= 1 in the MSH), deterministic output.
usage: quad_mesh_test.py CLI SHARED_DIR [--tier fast|slow]
fast: a few small models at --hmax-rel 0.05, quad fraction >= 0.95, each also with --quad-method
morph and mixed (same checks; the report names the method); slow: every public model at the issue's
sizes (--hmax-rel 0.02 --curvature-ratio 0.26 --anisotropy 1), quad fraction >= 0.98 (default method)."""
import filecmp, json, os, subprocess, sys, tempfile
import numpy as np, meshio

cli, shared = sys.argv[1], sys.argv[2]
tier = sys.argv[4] if len(sys.argv) > 4 and sys.argv[3] == "--tier" else "fast"
models = os.path.join(shared, "models")
manifest = [m for m in json.load(open(os.path.join(models, "MANIFEST.json"))) if "error" not in m]
FAST = {"box.brep", "cylinder.brep", "rod.brep", "cube_filet.stp", "part.step"}
if tier == "fast":
    manifest = [m for m in manifest if m["file"] in FAST]
    # at the thesis' curvature γ_c 0.15 (the program's 12 per circle leaves a fillet one
    # or two rows of quads and a cylinder's facets 1.1 % short of its area)
    extra, min_fraction = ["--hmax-rel", "0.05", "--curvature-ratio", "0.15"], 0.95
else:
    extra, min_fraction = ["--hmax-rel", "0.02", "--curvature-ratio", "0.26", "--anisotropy", "1"], 0.98

def measure(path):
    M = meshio.read(path); P = np.asarray(M.points, float)
    Q = [np.asarray(c.data) for c in M.cells if c.type == "quad"]; T = [np.asarray(c.data) for c in M.cells if c.type == "triangle"]
    Q = np.vstack(Q) if Q else np.zeros((0, 4), int); T = np.vstack(T) if T else np.zeros((0, 3), int)
    tri = np.vstack([T, Q[:, [0, 1, 2]], Q[:, [0, 2, 3]]])
    area = 0.5 * np.linalg.norm(np.cross(P[tri[:, 1]] - P[tri[:, 0]], P[tri[:, 2]] - P[tri[:, 0]]), axis=1).sum()
    E = np.vstack([T[:, [0, 1]], T[:, [1, 2]], T[:, [2, 0]], Q[:, [0, 1]], Q[:, [1, 2]], Q[:, [2, 3]], Q[:, [3, 0]]])
    _, cnt = np.unique(np.sort(E, axis=1), axis=0, return_counts=True)
    sj = np.ones(len(Q))
    for k in range(4):
        o, u, v = P[Q[:, k]], P[Q[:, (k + 1) % 4]], P[Q[:, (k + 3) % 4]]
        e1, e2 = u - o, v - o
        sj = np.minimum(sj, np.linalg.norm(np.cross(e1, e2), axis=1) /
                        np.maximum(np.linalg.norm(e1, axis=1) * np.linalg.norm(e2, axis=1), 1e-300))
    dims = M.point_data["gmsh:dim_tags"][:, 0]
    near = (dims[Q] <= 1).any(axis=1) if len(Q) else np.zeros(0, bool)
    layer = (int(near.sum()), float(sj[near].mean()) if near.any() else 0.0)
    return len(Q), len(T), float(sj.min()) if len(Q) else 0.0, area, int((cnt == 1).sum()), layer

t = tempfile.mkdtemp()
failed, passed = [], 0
runs = [(m, None) for m in manifest]
if tier == "fast": runs += [(m, meth) for meth in ("morph", "mixed") for m in manifest]
for m, method in runs:
    out, out2, rep = (os.path.join(t, x) for x in ("a.msh", "b.msh", "r.json"))
    for x in (out, out2, rep):
        if os.path.exists(x): os.remove(x)
    cmd = [cli, "mesh", os.path.join(models, m["file"]), "--dim", "2", "--quad"] + extra
    if method: cmd += ["--quad-method", method]
    name = m["file"] + (f" ({method})" if method else "")
    try:
        p = subprocess.run(cmd + ["-o", out, "--report", rep], capture_output=True, text=True, timeout=900)
    except subprocess.TimeoutExpired:
        failed.append(f"{name}: timeout"); continue
    if p.returncode != 0:
        failed.append(f"{name}: exit {p.returncode}: {p.stderr.strip()[-200:]}"); continue
    r = json.load(open(rep))
    nq, nt, sj, area, open_edges, layer = measure(out)
    cad = r["model"]["unique_face_area"]
    frac = nq / max(nq + nt, 1)
    why = []
    if r["status"] != "ok": why.append(f"status {r['status']}")
    if frac < min_fraction: why.append(f"quad fraction {frac:.3f} < {min_fraction}")
    if sj < 0.1: why.append(f"min scaled Jacobian {sj:.3f}")
    if m["solids"] > 0 and open_edges: why.append(f"{open_edges} open edges")
    if abs(area - cad) > 0.01 * cad: why.append(f"area off by {(area - cad) / cad:.2%}")
    if r["counts"]["quads"] != nq or r["counts"]["triangles"] != nt: why.append("report and file disagree on the counts")
    qb = r["quality"].get("quad", {})
    if abs(qb.get("fraction", -1) - frac) > 1e-9: why.append("report's quad fraction differs from the file's")
    if qb.get("scaled_jacobian", {}).get("min", -1) > sj + 1e-6: why.append("report's min scaled Jacobian above the file's")
    bl = qb.get("boundary_scaled_jacobian", {})
    if bl.get("quads") != layer[0] or abs(bl.get("mean", -1) - layer[1]) > 1e-6:
        why.append(f"report's boundary layer {bl} differs from the file's ({layer[0]} quads, mean {layer[1]:.6f})")
    if r["options"].get("quad_method") != (method or "merge"): why.append(f"report's quad_method {r['options'].get('quad_method')}")
    if tier == "fast":
        subprocess.run(cmd + ["-o", out2], capture_output=True, timeout=900)
        if not filecmp.cmp(out, out2, shallow=False): why.append("output differs between two runs")
    if why: failed.append(f"{name}: " + "; ".join(why))
    else:
        passed += 1
        print(f"ok {name}: {nq} quads {nt} triangles ({100 * frac:.1f}%), min scaled Jacobian {sj:.3f}, "
              f"mean {qb['scaled_jacobian']['mean']:.3f}, boundary layer {bl['mean']:.3f}, mu_M {qb['mu_M']['mean']:.3f}", flush=True)
for f in failed: print("FAIL", f)
print(f"{passed}/{len(runs)} quad meshes passed")
sys.exit(1 if failed else 0)
