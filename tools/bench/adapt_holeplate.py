#!/usr/bin/python3
"""Benchmark of `anisomesh adapt` with CalculiX (issue 19): the stress concentration factor
of a plate with a central hole in tension, uniform meshes against adapted ones.

models/holeplate.step: plate 200 × 100 × 5, hole Ø20 at its centre (d/W = 0.2). Steel
(E 210000 MPa, ν 0.3), quadratic tetrahedra (C3D10, --order 2). The end x = 0 is held in x
only (its node nearest (0, 50, 2.5) in y and z, the one nearest (0, 0, 2.5) in z: no rigid
motion, free contraction); the end x = 200 is pulled by a traction of 100 MPa (*DSLOAD on
its element faces). K_t = the largest nodal von Mises stress on the hole's surface / the
net-section stress 100 · W / (W - d) = 125 MPa. Peterson's chart (Heywood's fit
2 + (1 - d/W)³) gives 2.51 for a thin plate; the reference here is the finest uniform run.

Uniform: meshes of size h (--size h --no-curvature). Adapted: level 0 the uniform mesh of size
H0, level k adapted (anisomesh adapt --field STRESS, von Mises) from level k-1's .frd to the
level's node count. Printed: nodes, K_t and its error against the reference per run, and
the node counts each sequence needs for 1 % (the first run within 1 % from which on every
finer run stays within it).

usage: adapt_holeplate.py --cli BUILD/anisomesh [--models DIR] [--quick] [--keep DIR]
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "examples", "adapt_ccx"))
import ccxlib  # noqa: E402

LENGTH, WIDTH, THICKNESS, HOLE = 200.0, 100.0, 5.0, 20.0
CENTRE = (100.0, 50.0)
TRACTION = 100.0
NOMINAL = TRACTION * WIDTH / (WIDTH - HOLE)
PETERSON = 2 + (1 - HOLE / WIDTH) ** 3
ON_HOLE = 1e-3 * HOLE  # a node within this of the hole's radius lies on it
# The plate is as thick as a size-5 element: the thin-wall rule keeps every mesh at h ≤ 5
# (17632 nodes, C3D10), so the adapted counts asked lie above that.
UNIFORM_SIZES = [5, 3.5, 2.5]
REFERENCE_SIZE = 1.8
H0 = 5.0
ADAPT_TARGETS = [22000, 32000, 50000]
QUICK = {"uniform": [5, 3.5], "reference": 2.5, "adapt": [25000, 35000]}
TOLERANCE = 0.01


def faces_at_ends(inp):
    """The node sets FACE<n> of the ends x = 0 and x = LENGTH (found from their nodes)."""
    nodes = ccxlib.inp_nodes(inp)
    tol = 1e-6 * LENGTH
    return ccxlib.face_with_nodes_at(inp, 0, 0.0, tol, nodes), ccxlib.face_with_nodes_at(inp, 0, LENGTH, tol, nodes), nodes


def nearest(nodes, ids, p):
    return min(ids, key=lambda i: sum((a - b) ** 2 for a, b in zip(nodes[i], p)))


def solve(d):
    """Writes d/job.inp around d/mesh.inp, runs ccx; returns (nodes, K_t)."""
    fixed, loaded, nodes = faces_at_ends(os.path.join(d, "mesh.inp"))
    end = ccxlib.inp_nset(os.path.join(d, "mesh.inp"), f"FACE{fixed}")
    a = nearest(nodes, end, (0, WIDTH / 2, THICKNESS / 2))
    b = nearest(nodes, end, (0, 0, THICKNESS / 2))
    ccxlib.static_steel_deck(d, f"""
*BOUNDARY
FACE{fixed}, 1, 1, 0.
{a}, 2, 3, 0.
{b}, 3, 3, 0.
*DSLOAD
S_FACE{loaded}, P, {-TRACTION}
*NODE FILE
U
*EL FILE
S""")
    ccxlib.run_ccx(d)
    vm = ccxlib.frd_mises(os.path.join(d, "job.frd"))
    hole = [i for i, p in nodes.items()
            if abs(math.hypot(p[0] - CENTRE[0], p[1] - CENTRE[1]) - HOLE / 2) < ON_HOLE]
    return len(nodes), max(vm[i] for i in hole) / NOMINAL


def mesh_uniform(cli, model, d, h):
    ccxlib.mesh_c3d10(cli, ["mesh", model, "--dim", "3", "--size", repr(h), "--no-curvature"], d)
    return solve(d)


def mesh_adapted(cli, model, d, prev, target):
    ccxlib.mesh_c3d10(cli, ["adapt", model, "--from", os.path.join(prev, "job.frd"), "--field", "STRESS",
                            "--target-nodes", str(target)], d)
    return solve(d)


def nodes_for(rows, ref):
    """The fewest nodes from which on every run of the sequence is within TOLERANCE of ref."""
    best = None
    for n, kt, *_ in reversed(rows):
        if abs(kt / ref - 1) > TOLERANCE:
            break
        best = n
    return best


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", required=True)
    ap.add_argument("--models", default=os.path.join(here, "..", "..", "models"))
    ap.add_argument("--quick", action="store_true", help="fewer and coarser runs")
    ap.add_argument("--keep", help="keep the runs in this folder")
    a = ap.parse_args()
    cli, model = os.path.abspath(a.cli), os.path.join(a.models, "holeplate.step")
    sizes = QUICK["uniform"] if a.quick else UNIFORM_SIZES
    ref_size = QUICK["reference"] if a.quick else REFERENCE_SIZE
    targets = QUICK["adapt"] if a.quick else ADAPT_TARGETS
    work = a.keep or tempfile.mkdtemp()
    t0 = time.time()
    uniform = []
    for k, h in enumerate(sizes):
        uniform.append((*mesh_uniform(cli, model, os.path.join(work, f"u{k}"), h), f"h {h}"))
    ref_nodes, ref = mesh_uniform(cli, model, os.path.join(work, "ref"), ref_size)
    if H0 in sizes:  # level 0 is that uniform run
        start, first = os.path.join(work, f"u{sizes.index(H0)}"), uniform[sizes.index(H0)]
    else:
        start = os.path.join(work, "a0")
        first = (*mesh_uniform(cli, model, start, H0), f"h {H0}")
    adapted = [first]
    for k, n in enumerate(targets, 1):
        prev = start if k == 1 else os.path.join(work, f"a{k - 1}")
        adapted.append((*mesh_adapted(cli, model, os.path.join(work, f"a{k}"), prev, n),
                        f"{n} asked"))
    print(f"### Plate with a hole in tension, C3D10: K_t against nodes ({time.time() - t0:.0f} s)\n")
    print(f"reference: uniform h {ref_size}, {ref_nodes} nodes, K_t {ref:.4f} (Peterson, thin plate: {PETERSON:.3f})\n")
    print("| run | mesh | nodes | K_t | error vs reference |")
    print("|---|---|---:|---:|---:|")
    for name, rows in (("uniform", uniform), ("adapted", adapted)):
        for n, kt, what in rows:
            print(f"| {name} | {what} | {n} | {kt:.4f} | {100 * (kt / ref - 1):+.2f} % |")
    nu, na = nodes_for(uniform, ref), nodes_for(adapted, ref)
    print(f"\nnodes for K_t within {100 * TOLERANCE:.0f} %: uniform {nu or 'none of the runs'}, "
          f"adapted {na or 'none of the runs'}"
          + (f" (ratio {nu / na:.1f})" if nu and na else ""))
    if not a.keep:
        subprocess.run(["rm", "-rf", work])


if __name__ == "__main__":
    main()
