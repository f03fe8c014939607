"""The thesis' CYLINDER2 (table 5.6, issue 5 §2): the cylinder r = 1, length 10 with maximum
anisotropy γ_a = 10 meshes with metric mean ratio η_M ≥ 0.75 and mean metric edge length
μ_M within 1.00 ± 0.05, both as the report gives them: in M_v, the metric the tetrahedra are
made, improved and measured in (VolumeControlSpace.h). Also: status ok, no inverted tet and
the CAD volume within 1% (the referee meshq.py), the same bytes with --threads 2.
Runs in well under a second.

usage: cylinder2_test.py ANISOMESH SHARED_DIR
"""
import json
import math
import os
import subprocess
import sys
import tempfile

CLI, SHARED = sys.argv[1], sys.argv[2]
MODEL = os.path.join(SHARED, "bench", "cylinder_r1_l10.step")
MESHQ = os.path.join(SHARED, "tools", "meshq.py")
# the thesis' table (the program's defaults are Gmsh-like: 12 per circle, h_max diagonal / 10)
OPTIONS = ["--dim", "3", "--anisotropy", "10", "--curvature-ratio", "0.15", "--hmax-rel", "0.5"]
ETA_MIN, MU_TOL = 0.75, 0.05

failures = []
tmp = tempfile.mkdtemp()


def run(threads):
    out, rep = os.path.join(tmp, f"c{threads}.msh"), os.path.join(tmp, f"c{threads}.json")
    p = subprocess.run([CLI, "mesh", MODEL, "-o", out, "--report", rep, "--threads", str(threads), "-q", *OPTIONS],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"FAIL: anisomesh exited {p.returncode}: {p.stderr.strip()}")
    with open(rep) as f:
        return out, json.load(f)


out, report = run(1)
q = report["quality"]["volume"]
eta, mu = q["eta_M"]["mean"], q["mu_M"]["mean"]
if report["status"] != "ok":
    failures.append(f"status {report['status']}")
if not eta >= ETA_MIN:
    failures.append(f"eta_M {eta:.4f} < {ETA_MIN}")
if not abs(mu - 1) <= MU_TOL:
    failures.append(f"mu_M {mu:.4f} (in M_v) not within 1 +- {MU_TOL}")

ref = subprocess.run(["/usr/bin/python3", MESHQ, out], capture_output=True, text=True)
if ref.returncode != 0:
    failures.append(f"meshq failed: {ref.stderr.strip()}")
else:
    r = json.loads(ref.stdout)
    if r["inverted"] != 0:
        failures.append(f"{r['inverted']} inverted tets")
    if abs(r["volume"] - 10 * math.pi) > 0.01 * 10 * math.pi:
        failures.append(f"volume {r['volume']:.4f} not within 1% of 10 pi")

out2, _ = run(2)
with open(out, "rb") as a, open(out2, "rb") as b:
    if a.read() != b.read():
        failures.append("--threads 2 writes other bytes than --threads 1")

user = q.get("mu_M_user", {}).get("mean", float("nan"))
print(f"CYLINDER2: {report['counts']['tetrahedra']} tets, eta_M {eta:.4f}, mu_M {mu:.4f} (M_v), mu_M_user {user:.4f}")
if failures:
    print("FAIL: " + "; ".join(failures))
    sys.exit(1)
print("OK")
