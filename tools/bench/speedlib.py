"""Shared helpers of the side-by-side speed scripts (surface_speed.py, volume_speed.py):
whole-process wall time (median of N runs) and peak memory (max RSS, /usr/bin/time), the
element count and the referee's quality (../shared/tools/meshq.py) of the file written."""
import os, statistics, subprocess, sys

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.abspath(os.path.join(here, "..", ".."))
shared = os.path.abspath(os.path.join(root, "..", "shared"))
sys.path.insert(0, os.path.join(shared, "tools"))
import meshq  # noqa: E402


def cli_and_runs(argv):
    """(CLI path, runs) from the command line: [CLI] [--runs N]."""
    cli = argv[1] if len(argv) > 1 and not argv[1].startswith("--") else os.path.join(root, "build", "anisomesh")
    runs = int(argv[argv.index("--runs") + 1]) if "--runs" in argv else 3
    return cli, runs


def timed(cmd):
    """(seconds, peak bytes) of one run, or None when it failed."""
    p = subprocess.run(["/usr/bin/time", "-f", "%e %M"] + cmd, capture_output=True, text=True, timeout=3600)
    if p.returncode != 0:
        return None
    e, m = p.stderr.strip().splitlines()[-1].split()
    return float(e), int(m) * 1024


def measure(cmd, out, runs, kind, coarse=None):
    """Runs cmd `runs` times; kind 'tris' or 'tets' is what is counted. `coarse` is the same
    command at a size giving a handful of elements: its peak is the process's own footprint,
    subtracted for the net bytes per element."""
    base = timed(coarse) if coarse else None
    results = []
    for _ in range(runs):
        r = timed(cmd)
        if r is None:
            return None
        results.append(r)
    q = meshq.stats(out)
    n = q.get(kind, 0)
    s = statistics.median(x[0] for x in results)
    peak = max(x[1] for x in results)
    eta = q.get("tri_eta_avg") if kind == "tris" else q.get("eta_avg")
    return {"s": s, "peak_MB": peak / 2**20, "n": n, "B_per": peak / max(n, 1),
            "net_B_per": (peak - base[1]) / max(n, 1) if base else None, "per_s": n / s if s > 0 else 0,
            "eta": eta, "dihedral_min": q.get("dihedral_min")}


def print_table(rows, unit):
    print(f"{'case':<24} {'mesher':<16} {'time s':>8} {'peak MB':>8} {unit:>10} {'B/el':>7} {'net B/el':>8} "
          f"{unit + '/s':>10} {'mean ratio':>10} {'min dihedral':>12}")
    for case, who, r in rows:
        if r is None:
            print(f"{case:<24} {who:<16} failed")
            continue
        net = "%.0f" % r["net_B_per"] if r["net_B_per"] else "-"
        dih = "%.1f" % r["dihedral_min"] if r["dihedral_min"] is not None else "-"
        print(f"{case:<24} {who:<16} {r['s']:>8.2f} {r['peak_MB']:>8.1f} {r['n']:>10} {r['B_per']:>7.0f} {net:>8} "
              f"{r['per_s']:>10.0f} {r['eta']:>10} {dih:>12}")
