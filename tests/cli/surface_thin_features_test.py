#!/usr/bin/python3
"""Surface quality at thin faces and strips (issue 4), judged by the referee (meshq.py) at the
issue's options (--hmax-rel 0.02 --curvature-ratio 0.26 --anisotropy 1):
  SlenderSurface.brep (a face 3.8e-4 wide, below h_min = 1e-3): mean ratio >= 0.9, no needle;
  wing_fuselage.step (a trailing-edge band 1.3 wide, 380 long) and Block.stp: no triangle with
  mean ratio < 0.1.
usage: surface_thin_features_test.py CLI SHARED_DIR"""
import contextlib, io, os, subprocess, sys, tempfile

cli, shared = sys.argv[1], sys.argv[2]
sys.path.insert(0, os.path.join(shared, "tools"))
import meshq  # the referee

CASES = [("SlenderSurface.brep", 0.9), ("wing_fuselage.step", None), ("Block.stp", None)]
t = tempfile.mkdtemp()
failed = []
for name, min_avg in CASES:
    out = os.path.join(t, "out.msh")
    if os.path.exists(out):
        os.remove(out)
    cmd = [cli, "mesh", os.path.join(shared, "models", name), "-o", out, "--dim", "2", "--hmax-rel", "0.02",
           "--curvature-ratio", "0.26", "--anisotropy", "1"]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if p.returncode != 0 or not os.path.exists(out):
        failed.append(f"{name}: exit {p.returncode}: {p.stderr.strip()[-200:]}")
        continue
    with contextlib.redirect_stdout(io.StringIO()):
        q = meshq.stats(out)
    print(f"{name}: {q['tris']} triangles, mean ratio avg {q['tri_eta_avg']} min {q['tri_eta_min']}, "
          f"{q['tri_eta_lt_0.1']} below 0.1")
    if q["tri_eta_lt_0.1"]:
        failed.append(f"{name}: {q['tri_eta_lt_0.1']} triangles with mean ratio < 0.1")
    if min_avg is not None and q["tri_eta_avg"] < min_avg:
        failed.append(f"{name}: mean ratio avg {q['tri_eta_avg']} < {min_avg}")
for f in failed:
    print("FAIL", f)
sys.exit(1 if failed else 0)
