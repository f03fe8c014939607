#!/usr/bin/python3
"""Benchmark of `anisomesh adapt` on analytic fields (issue 19): interpolation error versus
node count for uniform meshes, isotropic adaptation (γ_a = 1) and anisotropic adaptation
(γ_a = 10), on the unit square (2D) and the unit cube (3D, models/cube.step scaled by 1/10).

Fields (adaptlib.py): f = tanh(50 (|x - c|² - 0.09)), c the centre, and f = exp(-x / 0.02).
Each adaptive level k adapts level k-1's mesh (level 0: a uniform mesh of the first count)
to the field sampled at its nodes, asking the level's node count. The error of the P1
interpolant of f at the new mesh's nodes against the exact f is measured here by a
Duffy-collapsed Gauss rule on every element (L2; L∞ the max over the same points).

Printed per case: nodes, L2, rate (-d log L2 / d log N; optimal 2/d), L∞, μ_M and η_M (the
report's metric quality), and at the anisotropic meshes' counts the error ratios
uniform / anisotropic and isotropic / anisotropic (log-log interpolation of those curves).

usage: adapt_analytic.py --cli BUILD/anisomesh [--models DIR] [--quick] [--dim 2|3] [--field tanh|layer]
"""
import argparse
import os
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import adaptlib  # noqa: E402

TARGETS = {2: [500, 1000, 2000, 4000, 8000], 3: [1000, 2000, 4000, 8000, 16000]}
QUICK_LEVELS = 3
VARIANTS = ["uniform", "iso", "aniso"]


def table(case, field, targets):
    t0 = time.time()
    seqs = {v: adaptlib.sequence(case, field, targets, v, f"{case.d}d-{field}") for v in VARIANTS}
    print(f"\n### {case.d}D, {field}: {'unit square' if case.d == 2 else 'unit cube'}, "
          f"optimal L2 rate {2 / case.d:.2f}  ({time.time() - t0:.0f} s)\n")
    print("| variant | nodes | L2 | rate | L∞ | μ_M | η_M | uniform / aniso | iso / aniso |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for v in VARIANTS:
        rows = seqs[v]
        for row, rate in zip(rows, adaptlib.rates(rows)):
            n, l2, linf, mu, eta = row
            ratios = ["", ""]
            if v == "aniso":
                ratios = [f"{adaptlib.error_at(seqs[o], n) / l2:.1f}" for o in ("uniform", "iso")]
            r = "" if rate is None else f"{rate:.2f}"
            print(f"| {v} | {n} | {l2:.3e} | {r} | {linf:.3e} | {mu:.3f} | {eta:.3f} | {ratios[0]} | {ratios[1]} |")
    fit = {v: -adaptlib.slope(seqs[v]) for v in VARIANTS}
    print("\nleast-squares rates over the levels: " + ", ".join(f"{v} {fit[v]:.2f}" for v in VARIANTS))
    sys.stdout.flush()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cli", required=True, help="the anisomesh binary")
    ap.add_argument("--models", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "models"))
    ap.add_argument("--quick", action="store_true", help=f"{QUICK_LEVELS} levels instead of 5")
    ap.add_argument("--dim", type=int, choices=[2, 3], action="append", help="2, 3 or both (default)")
    ap.add_argument("--field", choices=list(adaptlib.FIELDS), action="append", help="default: both")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as work:
        for d in a.dim or [2, 3]:
            case = adaptlib.Case(os.path.abspath(a.cli), work, d, a.models)
            targets = TARGETS[d][:QUICK_LEVELS] if a.quick else TARGETS[d]
            for field in a.field or list(adaptlib.FIELDS):
                table(case, field, targets)


if __name__ == "__main__":
    main()
