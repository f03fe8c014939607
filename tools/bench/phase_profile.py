#!/usr/bin/python3
"""Where the time goes on real parts (issue 18): per-phase times of whole runs, per boundary
triangle for the boundary-driven phases and per tetrahedron for the others, side by side with
Gmsh 4.8's HXT in the same run.
usage: tools/bench/phase_profile.py [CLI] [--runs N] [--threads T] [--options "..."] [MODEL ...]
Defaults: the largest public models (Block.stp, U_Joint_2.stp, SampleCrankshaft4A.stp in
../shared/models) at the issue-20 options (--hmax-rel 0.02 --curvature-ratio 0.26 --anisotropy 1),
one thread, 3 runs (the run of median total time is reported). The phases are the report's
`times` (volume phases summed over solids). Gmsh HXT meshes the same model at a uniform size:
our mean volume edge length, then corrected once for our tetrahedron count (both counts are
printed), with the same threads; time per tetrahedron is compared, whole process."""
import json, os, statistics, subprocess, sys, tempfile

from speedlib import root, shared, timed

BOUNDARY = ["volume boundary", "volume triangulation", "volume recovery", "volume carving", "volume control space"]
VOLUME = ["volume refinement", "volume improvement", "volume quality"]
SURFACE = ["read", "prepare", "contours", "faces", "surface repair"]


def arg(name, default):
    return sys.argv[sys.argv.index(name) + 1] if name in sys.argv else default


args = [a for i, a in enumerate(sys.argv[1:], 1)
        if not a.startswith("--") and sys.argv[i - 1] not in ("--runs", "--threads", "--options")]
cli = args[0] if args and os.access(args[0], os.X_OK) and not args[0].endswith((".stp", ".step", ".brep")) \
    else os.path.join(root, "build", "anisomesh")
models = [a for a in args if a != cli] or [os.path.join(shared, "models", m) for m in
                                           ("Block.stp", "U_Joint_2.stp", "SampleCrankshaft4A.stp")]
runs = int(arg("--runs", "3"))
threads = arg("--threads", "1")
options = arg("--options", "--hmax-rel 0.02 --curvature-ratio 0.26 --anisotropy 1").split()
t = tempfile.mkdtemp()


def ours(model):
    """(wall s, peak bytes, report) of the run of median wall time."""
    done = []
    for k in range(runs):
        rep = f"{t}/r{k}.json"
        r = timed([cli, "mesh", model, "-o", f"{t}/a.msh", "-q", "--threads", threads, "--report", rep] + options)
        if r is None:
            return None
        done.append((r[0], r[1], json.load(open(rep))))
    done.sort(key=lambda x: x[0])
    return done[len(done) // 2]


def gmsh_hxt(model, h):
    out = f"{t}/g.msh"
    rs = [timed(["gmsh", model, "-3", "-algo", "hxt", "-clmin", str(h), "-clmax", str(h), "-nt", threads, "-v", "0",
                 "-format", "msh41", "-o", out]) for _ in range(runs)]
    if any(r is None for r in rs):
        return None
    p = subprocess.run(["/usr/bin/python3", os.path.join(shared, "tools", "meshq.py"), out], capture_output=True,
                       text=True, timeout=3600)
    q = json.loads(p.stdout.strip().splitlines()[-1]) if p.returncode == 0 else {}
    return statistics.median(r[0] for r in rs), q.get("tets", 0), q.get("eta_avg")


for model in models:
    name = os.path.basename(model)
    r = ours(model)
    if r is None:
        print(f"{name}: anisomesh failed")
        continue
    wall, peak, rep = r
    times, counts = rep["times"], rep["counts"]
    tris, tets = counts.get("triangles", 0), counts.get("tetrahedra", 0)
    print(f"\n{name} ({' '.join(options)}, {threads} thread(s), median of {runs}): {tris} boundary triangles, "
          f"{tets} tetrahedra, {wall:.2f} s wall, peak {peak / 2**20:.0f} MB")
    print(f"  {'phase':<24} {'s':>8} {'share':>6} {'us/triangle':>12} {'us/tet':>8}")
    for group in (SURFACE, BOUNDARY, VOLUME):
        for ph in group:
            s = times.get(ph)
            if s is None:
                continue
            per = f"{1e6 * s / max(tris, 1):12.2f}" if group is not VOLUME else " " * 12
            pert = f"{1e6 * s / max(tets, 1):8.2f}" if group is not SURFACE else " " * 8
            print(f"  {ph:<24} {s:8.2f} {100 * s / times['total']:5.1f}% {per} {pert}")
    b = sum(times.get(p, 0) for p in BOUNDARY)
    v = sum(times.get(p, 0) for p in ("volume refinement", "volume improvement"))
    print(f"  boundary-driven phases {b:.2f} s = {b / v if v else float('inf'):.2f} x (refinement + improvement, {v:.2f} s);"
          f" issue 18 asks <= 0.33")
    h = rep.get("sizing", {}).get("volume_edge_length", {}).get("mean")
    g = gmsh_hxt(model, round(h, 6)) if h else None
    if g is None:
        print("  gmsh hxt: failed")
        continue
    if g[1]:  # once more at the size that should give our count (tets scale as h^-3)
        h *= (g[1] / max(tets, 1)) ** (1 / 3)
        g = gmsh_hxt(model, round(h, 6)) or g
    gs, gtets, geta = g
    ratio = (wall / max(tets, 1)) / (gs / max(gtets, 1)) if gtets else float("inf")
    print(f"  gmsh hxt at h {h:.4g}: {gtets} tetrahedra in {gs:.2f} s (mean ratio {geta}); "
          f"our time per tetrahedron {ratio:.2f} x Gmsh's")
