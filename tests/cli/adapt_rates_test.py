#!/usr/bin/env python3
"""Convergence of `anisomesh adapt` on analytic fields (issue 19), the small cases of
tools/bench/adapt_analytic.py (whose adaptlib.py measures the error by its own quadrature):
the unit square, f = tanh(50 (|x - c|² - 0.09)) and f = exp(-x / 0.02), two levels (LEVELS
node counts asked) of uniform meshes, isotropic (γ_a = 1) and anisotropic (γ_a = 10)
adaptation. Checked per field:
  - the anisotropic L2 error falls with the node count at least at MIN_RATE (optimal: 1 in 2D);
  - at the anisotropic meshes' node counts, the uniform meshes' error (log-log interpolated)
    is at least UNIFORM_FACTOR and the isotropic adaptation's at least ISO_FACTOR times larger;
  - the adapted meshes' metric quality (the report's) holds: μ_M within 1 ± MU_TOL, η_M ≥ ETA_MIN.
With --dim 3 (the slow tier): the 10 mm cube (a unit cube at scale 10), the tanh field only,
LEVELS_3D, the optimal rate 2/3 and η_M ≥ 0.75 (the issue's bars; measured in docs/adapt.md).
usage: adapt_rates_test.py CLI MODELS_DIR SOURCE_DIR [--dim 3]
"""
import os
import sys
import tempfile

from clitest import check, failures

cli, models, src = sys.argv[1], sys.argv[2], sys.argv[3]
dim = 3 if sys.argv[4:6] == ["--dim", "3"] else 2
sys.path.insert(0, os.path.join(src, "tools", "bench"))
import adaptlib  # noqa: E402

LEVELS = [1000, 2000] if dim == 2 else [2000, 4000]
MIN_RATE = 0.8 if dim == 2 else 0.6  # optimal: 1 in 2D, 2/3 in 3D
FIELDS = adaptlib.FIELDS if dim == 2 else ["tanh"]
UNIFORM_FACTOR = {"tanh": 5, "layer": 5}
ISO_FACTOR = {"tanh": 2, "layer": 2}
MU_TOL, ETA_MIN = 0.1, 0.8 if dim == 2 else 0.75
with tempfile.TemporaryDirectory() as t:
    case = adaptlib.Case(cli, t, dim, models)
    for field in FIELDS:
        seq = {v: adaptlib.sequence(case, field, LEVELS, v, field) for v in ("uniform", "iso", "aniso")}
        for v, rows in seq.items():
            print(f"     {field} {v}: " + ", ".join(f"{n} nodes L2 {l2:.3e} Linf {li:.3e} mu_M {mu:.3f} eta_M {eta:.3f}"
                                                   for n, l2, li, mu, eta in rows))
        rate = adaptlib.rates(seq["aniso"])[-1]
        check(rate >= MIN_RATE, f"{field}: anisotropic L2 rate {rate:.2f} (>= {MIN_RATE})")
        for n, l2, _, mu, eta in seq["aniso"]:
            fu = adaptlib.error_at(seq["uniform"], n) / l2
            fi = adaptlib.error_at(seq["iso"], n) / l2
            check(fu >= UNIFORM_FACTOR[field] and fi >= ISO_FACTOR[field],
                  f"{field}, {n} nodes: error uniform / aniso {fu:.1f} (>= {UNIFORM_FACTOR[field]}), "
                  f"iso / aniso {fi:.1f} (>= {ISO_FACTOR[field]})")
            check(abs(mu - 1) <= MU_TOL and eta >= ETA_MIN,
                  f"{field}, {n} nodes: mu_M {mu:.3f} (1 +- {MU_TOL}), eta_M {eta:.3f} (>= {ETA_MIN})")

print("adapt rates:", "FAILED " + "; ".join(failures) if failures else "all passed")
sys.exit(1 if failures else 0)
