#!/usr/bin/python3
"""Benchmark of `anisomesh adapt` with CalculiX (issue 19) where uniform refinement is slow:
an L-shaped plate with a sharp re-entrant corner, whose stress is singular there.

The model (made here with Gmsh's OpenCASCADE kernel, lbracket.step in the work folder): the
square 100 x 100 less its quarter [50, 100] x [50, 100], 10 thick (z). The end y = 100 of
the upright leg is clamped; the end x = 100 of the other leg is pulled along x by a traction
of 10 MPa (*DSLOAD, consistent with every mesh): the leg bends about the corner (50, 50),
where the stress grows as r^(lambda - 1), lambda = 0.544 for a 270 deg corner. Steel
(E 210000 MPa, nu 0.3), quadratic tetrahedra (C3D10, --order 2).

The measure is the strain energy U (ccx *EL PRINT ELSE, TOTALS=ONLY). A displacement
method under load converges to U from below and U_ref - U_h is the squared energy norm of
the error; the relative energy error is e = sqrt((U_ref - U_h) / U_ref). Uniform meshes
converge as N^(-lambda/3) (the singularity), an adapted sequence should beat that rate
(quadratic elements on a mesh graded to the singularity: up to N^(-2/3)). The reference
U_ref is an adapted run of REFERENCE_NODES (at least 2.5 times the largest compared run:
its own error, much below theirs, makes theirs read slightly low).

Uniform: meshes of size h (--size h). Adapted: level 0 the uniform mesh of size H0, level
k adapted (anisomesh adapt --field STRESS, von Mises) from level k-1's .frd. Printed: nodes,
U, e per run, the least-squares rate of each sequence, and the nodes each needs for e below
the finest uniform run's error.

usage: adapt_lbracket.py --cli BUILD/anisomesh [--quick] [--keep DIR]   (/usr/bin/python3: gmsh)
"""
import argparse
import math
import os
import re
import subprocess
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "examples", "adapt_ccx"))
import ccxlib  # noqa: E402

SIDE, NOTCH, THICKNESS, TRACTION = 100.0, 50.0, 10.0, 10.0
UNIFORM_SIZES = [10, 7, 5, 3.5]
H0 = 10.0
ADAPT_TARGETS = [6000, 12000, 24000]
REFERENCE_NODES = 60000
QUICK = {"uniform": [10, 7, 5], "adapt": [5000, 10000], "reference": 25000}


def make_model(path):
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Verbosity", 0)
    occ = gmsh.model.occ
    outer = occ.addBox(0, 0, 0, SIDE, SIDE, THICKNESS)
    notch = occ.addBox(NOTCH, NOTCH, 0, SIDE - NOTCH, SIDE - NOTCH, THICKNESS)
    occ.cut([(3, outer)], [(3, notch)])
    occ.synchronize()
    sys.stdout.flush()
    saved = os.dup(1)  # OpenCASCADE's STEP writer prints its statistics on stdout
    with open(os.devnull, "w") as null:
        os.dup2(null.fileno(), 1)
        try:
            gmsh.write(path)
        finally:
            os.dup2(saved, 1)
            os.close(saved)
    gmsh.finalize()


def solve(d):
    """Writes d/job.inp around d/mesh.inp, runs ccx; returns (nodes, strain energy)."""
    inp = os.path.join(d, "mesh.inp")
    nodes = ccxlib.inp_nodes(inp)
    tol = 1e-6 * SIDE
    clamped, pulled = (ccxlib.face_with_nodes_at(inp, axis, SIDE, tol, nodes) for axis in (1, 0))
    ccxlib.static_steel_deck(d, f"""
*BOUNDARY
FACE{clamped}, 1, 3, 0.
*DSLOAD
S_FACE{pulled}, P, {-TRACTION}
*EL PRINT, ELSET=EALL, TOTALS=ONLY
ELSE
*EL FILE
S""")
    ccxlib.run_ccx(d)
    text = open(os.path.join(d, "job.dat")).read()
    m = re.findall(r"total internal energy.*?\n\s*\n?\s*([-+0-9.Ee]+)", text, re.S | re.I)
    if not m:
        raise RuntimeError(f"{d}: no total internal energy in job.dat")
    return len(nodes), float(m[-1])


def mesh_uniform(cli, model, d, h):
    ccxlib.mesh_c3d10(cli, ["mesh", model, "--dim", "3", "--size", repr(h)], d)
    return solve(d)


def mesh_adapted(cli, model, d, prev, target):
    ccxlib.mesh_c3d10(cli, ["adapt", model, "--from", os.path.join(prev, "job.frd"), "--field", "STRESS",
                            "--target-nodes", str(target)], d)
    return solve(d)


def rate(rows, ref):
    """Least-squares slope of log(e) against log(N) over the rows (those with e > 0)."""
    pts = [(math.log(n), math.log(e)) for n, u, _ in rows if (e := energy_error(u, ref)) > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sum((x - mx) ** 2 for x, _ in pts)


def energy_error(u, ref):
    return math.sqrt(max(ref - u, 0.0) / ref)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", required=True)
    ap.add_argument("--quick", action="store_true", help="fewer and coarser runs")
    ap.add_argument("--keep", help="keep the runs in this folder")
    a = ap.parse_args()
    cli = os.path.abspath(a.cli)
    sizes = QUICK["uniform"] if a.quick else UNIFORM_SIZES
    targets = QUICK["adapt"] if a.quick else ADAPT_TARGETS
    ref_target = QUICK["reference"] if a.quick else REFERENCE_NODES
    work = a.keep or tempfile.mkdtemp()
    os.makedirs(work, exist_ok=True)
    model = os.path.join(work, "lbracket.step")
    make_model(model)
    t0 = time.time()
    uniform = [(*mesh_uniform(cli, model, os.path.join(work, f"u{k}"), h), f"h {h:g}") for k, h in enumerate(sizes)]
    start = os.path.join(work, f"u{sizes.index(H0)}")
    adapted = [uniform[sizes.index(H0)]]
    prev = start
    for k, n in enumerate(targets + [ref_target], 1):
        d = os.path.join(work, f"a{k}")
        adapted.append((*mesh_adapted(cli, model, d, prev, n), f"{n} asked"))
        prev = d
    ref_run = adapted.pop()
    ref = ref_run[1]
    print(f"### L-shaped plate, re-entrant corner, C3D10: strain energy against nodes ({time.time() - t0:.0f} s)\n")
    print(f"reference: adapted, {ref_run[0]} nodes, U_ref {ref:.6g} mJ\n")
    print("| run | mesh | nodes | U (mJ) | energy error |")
    print("|---|---|---:|---:|---:|")
    for name, rows in (("uniform", uniform), ("adapted", adapted)):
        for n, u, what in rows:
            print(f"| {name} | {what} | {n} | {u:.6g} | {100 * energy_error(u, ref):.2f} % |")
    ru, ra = rate(uniform, ref), rate(adapted, ref)
    print(f"\nrate of the energy error against nodes: uniform {ru if ru is None else f'{ru:.2f}'}, "
          f"adapted {ra if ra is None else f'{ra:.2f}'} (the singularity limits uniform meshes to about "
          f"{-0.544 / 3:.2f}; quadratic elements graded to it, up to {-2 / 3:.2f})")
    target = energy_error(uniform[-1][1], ref)
    better = [n for n, u, _ in adapted if energy_error(u, ref) <= target]
    print(f"nodes for the finest uniform run's error ({100 * target:.2f} %): uniform {uniform[-1][0]}, adapted "
          + (f"{min(better)} ({uniform[-1][0] / min(better):.1f}x fewer)" if better else "none of the runs"))
    if not a.keep:
        subprocess.run(["rm", "-rf", work])


if __name__ == "__main__":
    main()
