#!/usr/bin/python3
"""Surface meshing speed and memory, side by side with Gmsh 4.8 in the same run (issue 4 §2).
usage: tools/bench/surface_speed.py [CLI] [--runs N]
Whole process, one thread each, same uniform size; prints a table: wall time (median),
peak memory (max RSS), triangles, bytes per triangle, triangles per second, and the
referee's mean ratio (../shared/tools/meshq.py) for both. "net B/tri" subtracts the peak
memory of the same command at a size giving a handful of triangles (the process's own
footprint: libraries, OCCT, the model), i.e. what the mesh itself costs at peak.
Cases: the planar 2x1 face at size 0.004 (Gmsh -algo front2d), and the thesis' AN1
(anisotropic analytic metric; anisomesh only: Gmsh has no analytic anisotropic sizing)."""
import json, os, statistics, subprocess, sys, tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.abspath(os.path.join(here, "..", ".."))
shared = os.path.abspath(os.path.join(root, "..", "shared"))
cli = sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("--") else os.path.join(root, "build", "anisomesh")
runs = int(sys.argv[sys.argv.index("--runs") + 1]) if "--runs" in sys.argv else 3
sys.path.insert(0, os.path.join(shared, "tools"))
import meshq

t = tempfile.mkdtemp()

def peak_rss(cmd):
    p = subprocess.run(["/usr/bin/time", "-f", "%e %M"] + cmd, capture_output=True, text=True, timeout=1800)
    return int(p.stderr.strip().splitlines()[-1].split()[1]) * 1024 if p.returncode == 0 else 0

def measure(cmd, out, coarse=None):
    base = peak_rss(coarse) if coarse else 0
    times, rss = [], []
    for _ in range(runs):
        p = subprocess.run(["/usr/bin/time", "-f", "%e %M"] + cmd, capture_output=True, text=True, timeout=1800)
        if p.returncode != 0:
            return None
        e, m = p.stderr.strip().splitlines()[-1].split()
        times.append(float(e)); rss.append(int(m) * 1024)
    q = meshq.stats(out)
    n = q.get("tris", 0)
    return {"s": statistics.median(times), "peak_MB": max(rss) / 2**20, "tris": n,
            "B_per_tri": max(rss) / max(n, 1), "net_B_per_tri": (max(rss) - base) / max(n, 1) if base else None,
            "tri_per_s": n / statistics.median(times), "eta": q.get("tri_eta_avg")}

rect = os.path.join(shared, "bench", "rect_2x1.step")
an1 = os.path.join(shared, "bench", "AN1.json")
def ours(size):
    return [cli, "mesh", rect, "-o", f"{t}/a.msh", "--dim", "2", "--size", size, "--threads", "1"]

def theirs(size):
    return ["gmsh", rect, "-2", "-clmin", size, "-clmax", size, "-algo", "front2d", "-nt", "1", "-v", "0", "-format", "msh41",
            "-o", f"{t}/g.msh"]

rows = [
    ("rect 2x1 h=0.004", "anisomesh", measure(ours("0.004"), f"{t}/a.msh", ours("0.5"))),
    ("rect 2x1 h=0.004", "gmsh front2d", measure(theirs("0.004"), f"{t}/g.msh", theirs("0.5"))),
    ("AN1 (k=1)", "anisomesh", measure([cli, "mesh", an1, "-o", f"{t}/n.msh", "--dim", "2", "--threads", "1"], f"{t}/n.msh")),
]
print(f"{'case':<20} {'mesher':<14} {'time s':>8} {'peak MB':>8} {'triangles':>10} {'B/tri':>7} {'net B/tri':>9} {'tri/s':>10} {'referee mean ratio (Euclidean)':>10}")
for case, who, r in rows:
    if r is None:
        print(f"{case:<20} {who:<14} failed"); continue
    net = "%.0f" % r["net_B_per_tri"] if r["net_B_per_tri"] else "-"
    print(f"{case:<20} {who:<14} {r['s']:>8.2f} {r['peak_MB']:>8.1f} {r['tris']:>10} {r['B_per_tri']:>7.0f} {net:>9} {r['tri_per_s']:>10.0f} {r['eta']:>10}")
