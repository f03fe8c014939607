#!/usr/bin/python3
"""Default tet counts of anisomesh against Gmsh 4.8 with -clcurv 12 (issue 17).

Usage: /usr/bin/python3 tools/bench/defaults_vs_gmsh.py --cli build/anisomesh
           [--dir ../shared/models] [--only a.stp,b.brep] [--timeout 300] [--markdown]

Meshes every model with solids in DIR/MANIFEST.json, one run at a time: anisomesh at its
defaults (`mesh FILE -o out.msh`) and `gmsh -3 -clcurv 12 FILE -o out.msh`. Prints one row
per model: tets of both, their ratio, both wall times, and the referee's
(shared/tools/meshq.py) min dihedral angle and mean ratio average of both. A failed or
timed-out run shows its exit code in place of the counts."""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED = os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared"))


def run(cmd, timeout):
    t = time.monotonic()
    try:
        rc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        rc = "timeout"
    return rc, time.monotonic() - t


def referee(mesh):
    out = subprocess.run(["/usr/bin/python3", os.path.join(SHARED, "tools", "meshq.py"), mesh],
                         capture_output=True, text=True, timeout=600).stdout
    try:
        return json.loads(out.strip().splitlines()[-1])
    except (ValueError, IndexError):
        return {}


def measure(cmd, out, timeout):
    if os.path.exists(out):
        os.remove(out)
    rc, secs = run(cmd, timeout)
    q = referee(out) if rc == 0 and os.path.exists(out) else {}
    return {"rc": rc, "s": secs, "tets": q.get("tets"), "dih": q.get("dihedral_min"), "eta": q.get("eta_avg")}


def cell(v, fmt):
    return "-" if v is None else fmt % v


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", required=True)
    ap.add_argument("--dir", default=os.path.join(SHARED, "models"))
    ap.add_argument("--only", default="")
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--gmsh", default="gmsh")
    ap.add_argument("--markdown", action="store_true", help="a Markdown table (for docs/)")
    a = ap.parse_args()
    manifest = json.load(open(os.path.join(a.dir, "MANIFEST.json")))
    only = set(filter(None, a.only.split(",")))
    models = [m["file"] for m in manifest if m.get("solids", 0) > 0 and (not only or m["file"] in only)]
    head = ["model", "ours tets", "gmsh tets", "ratio", "ours s", "gmsh s", "ours min dih", "gmsh min dih",
            "ours eta avg", "gmsh eta avg"]
    if a.markdown:
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
    else:
        print("%-28s %9s %9s %6s %7s %7s %6s %6s %6s %6s" % tuple(head))
    tmp = tempfile.mkdtemp(prefix="defaults_vs_gmsh_")
    worst = 0.0
    for f in models:
        path = os.path.join(a.dir, f)
        ours = measure([a.cli, "mesh", path, "-o", os.path.join(tmp, "a.msh"), "-q"], os.path.join(tmp, "a.msh"), a.timeout)
        gmsh = measure([a.gmsh, "-3", "-clcurv", "12", path, "-o", os.path.join(tmp, "g.msh")], os.path.join(tmp, "g.msh"),
                       a.timeout)
        ratio = ours["tets"] / gmsh["tets"] if ours["tets"] and gmsh["tets"] else None
        if ratio:
            worst = max(worst, ratio, 1 / ratio)
        row = [f, ours["tets"] if ours["tets"] else "rc %s" % ours["rc"], gmsh["tets"] if gmsh["tets"] else "rc %s" % gmsh["rc"],
               cell(ratio, "%.2f"), cell(ours["s"], "%.1f"), cell(gmsh["s"], "%.1f"), cell(ours["dih"], "%.1f"),
               cell(gmsh["dih"], "%.1f"), cell(ours["eta"], "%.3f"), cell(gmsh["eta"], "%.3f")]
        if a.markdown:
            print("| " + " | ".join(str(x) for x in row) + " |", flush=True)
        else:
            print("%-28s %9s %9s %6s %7s %7s %6s %6s %6s %6s" % tuple(row), flush=True)
    print("\nlargest factor between the counts: %.2f" % worst)
    return 0


if __name__ == "__main__":
    sys.exit(main())
