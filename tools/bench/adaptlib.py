"""Helpers of the adapt benchmarks (adapt_analytic.py) and tests (tests/cli/adapt_rates_test.py):
the analytic fields of issue 19, an independent quadrature of the P1 interpolation error,
and the three mesh sequences compared (uniform, isotropic and anisotropic adaptation).
Needs numpy and meshio (/usr/bin/python3 on Debian)."""
import contextlib
import io
import json
import os
import subprocess

import meshio
import numpy as np

# The fields, on the unit square / cube (x holds d columns, in [0, 1]).
FRONT_CENTRE, FRONT_RADIUS, FRONT_STEEPNESS = 0.5, 0.3, 50.0
LAYER_DELTA = 0.02


def tanh_front(x):
    """f = tanh(50 (|x - c|² - r²)), c the domain's centre, r = 0.3."""
    return np.tanh(FRONT_STEEPNESS * (((x - FRONT_CENTRE) ** 2).sum(-1) - FRONT_RADIUS ** 2))


def boundary_layer(x):
    """f = exp(-x / δ), δ = 0.02."""
    return np.exp(-x[..., 0] / LAYER_DELTA)


FIELDS = {"tanh": tanh_front, "layer": boundary_layer}


def _gauss01(n):
    t, w = np.polynomial.legendre.leggauss(n)
    return (t + 1) / 2, w / 2


def simplex_rule(d, n):
    """Quadrature on the reference simplex (Duffy-collapsed n-point Gauss-Legendre per
    direction, exact for polynomials of degree 2n - d): barycentric
    coordinates (q × (d+1)) and weights summing to 1 (the element's measure factors out)."""
    t, w = _gauss01(n)
    if d == 2:
        u, v = np.meshgrid(t, t, indexing="ij")
        wu, wv = np.meshgrid(w, w, indexing="ij")
        x, y = u, v * (1 - u)
        wt = wu * wv * (1 - u) * 2
        bary = np.stack([1 - x - y, x, y], -1).reshape(-1, 3)
        return bary, wt.ravel()
    u, v, s = np.meshgrid(t, t, t, indexing="ij")
    wu, wv, ws = np.meshgrid(w, w, w, indexing="ij")
    x, y, z = u, v * (1 - u), s * (1 - u) * (1 - v)
    wt = wu * wv * ws * (1 - u) ** 2 * (1 - v) * 6
    bary = np.stack([1 - x - y - z, x, y, z], -1).reshape(-1, 4)
    return bary, wt.ravel()


def interpolation_error(points, cells, f, d, n=None, chunk=20000):
    """(L2, L∞) of f - Π f on the simplices `cells` (corner indices into `points`, already in
    unit coordinates), Π f the P1 interpolant of f at the corners: ∫ (f - Π f)² by the rule
    above on every element, the max over the same quadrature points."""
    bary, wt = simplex_rule(d, n or (6 if d == 2 else 5))
    P = points[:, :d]
    fv = f(P)
    total, peak = 0.0, 0.0
    for s in range(0, len(cells), chunk):
        c = cells[s:s + chunk]
        X = P[c]                                   # (e, d+1, d)
        J = X[:, 1:] - X[:, :1]                    # (e, d, d)
        measure = np.abs(np.linalg.det(J)) / (2 if d == 2 else 6)
        Q = np.einsum("qk,ekd->eqd", bary, X)
        err = f(Q) - np.einsum("qk,ek->eq", bary, fv[c])
        total += float(((err ** 2) @ wt * measure).sum())
        peak = max(peak, float(np.abs(err).max()))
    return np.sqrt(total), peak


def read_mesh(path):
    """meshio.read without the empty line meshio prints for our MSH files."""
    with contextlib.redirect_stdout(io.StringIO()):
        return meshio.read(path)


def read_simplices(path, d, scale):
    """The points (divided by `scale`) and the triangles (d = 2) or tetrahedra (d = 3) of a mesh."""
    m = read_mesh(path)
    key = "triangle" if d == 2 else "tetra"
    cells = np.vstack([b.data for b in m.cells if b.type == key])
    return m.points / scale, cells


class Case:
    """One domain: the unit square (an analytic plane) or models/cube.step (10 mm, scaled to 1)."""

    def __init__(self, cli, workdir, d, models):
        self.cli, self.work, self.d = cli, workdir, d
        if d == 2:
            self.model = os.path.join(workdir, "square.json")
            with open(self.model, "w") as fp:
                fp.write('{"name": "SQ", "surface": {"type": "plane"}, "domain": {"u": [0, 1], "v": [0, 1]}}')
            self.scale, self.dim_args = 1.0, ["--dim", "2"]
        else:
            self.model, self.scale, self.dim_args = os.path.join(models, "cube.step"), 10.0, ["--dim", "3"]

    def run(self, *args):
        r = subprocess.run([self.cli, *args, "-q"], capture_output=True, text=True, timeout=1800)
        if r.returncode != 0:
            raise RuntimeError(f"{' '.join(args[:2])}: exit {r.returncode}: {r.stderr.strip()[-300:]}")

    def uniform(self, out, h):
        """A mesh of size h (unit coordinates); returns its report."""
        self.run("mesh", self.model, "-o", out, *self.dim_args, "--size", repr(h * self.scale),
                 "--report", out + ".json")
        return load_report(out + ".json")

    def uniform_for(self, out, nodes):
        """A uniform mesh of about `nodes` nodes: the size guessed for equilateral elements,
        then corrected once by the count made."""
        h = (2 / (np.sqrt(3) * nodes)) ** 0.5 if self.d == 2 else (1 / (1.4 * nodes)) ** (1 / 3)
        rep = self.uniform(out, h)
        made = rep["counts"]["nodes"]
        if abs(made / nodes - 1) > 0.1:
            rep = self.uniform(out, h * (made / nodes) ** (1 / self.d))
        return rep

    def sample(self, mesh, field, out):
        """Writes `field` at the nodes of `mesh` as point data "f" of an MSH file."""
        m = read_mesh(mesh)
        key = "triangle" if self.d == 2 else "tetra"
        cells = [b for b in m.cells if b.type == key]
        meshio.Mesh(m.points, cells, point_data={"f": FIELDS[field](m.points[:, :self.d] / self.scale)}).write(
            out, file_format="gmsh", binary=True)

    def adapt(self, source, out, nodes, anisotropy):
        self.run("adapt", self.model, "--from", source, "--field", "f", "-o", out, "--target-nodes", str(nodes),
                 "--anisotropy", str(anisotropy), "--report", out + ".json")
        return load_report(out + ".json")

    def error(self, mesh, field):
        P, cells = read_simplices(mesh, self.d, self.scale)
        return interpolation_error(P, cells, FIELDS[field], self.d)


def load_report(path):
    with open(path) as fp:
        return json.load(fp)


def metric_quality(report, d):
    """(μ_M mean, η_M mean) of a run report: the surface's for d = 2, the tetrahedra's (in the
    metric of the tets, M_v) for d = 3."""
    q = report["quality"] if d == 2 else report["quality"]["volume"]
    return q["mu_M"]["mean"], q["eta_M"]["mean"]


def sequence(case, field, targets, variant, tag, passes=2):
    """Rows (nodes, L2, L∞, μ_M, η_M) of one variant over the node counts `targets`:
    'uniform' meshes of about each count; 'iso' / 'aniso' adaptation (γ_a = 1 / 10), level k
    adapted `passes` times to its count, the first pass from level k-1's mesh (level 0: the
    uniform mesh of targets[0] nodes), each from the field sampled at the previous mesh's nodes
    (a second pass at the same count brings mesh and metric together)."""
    rows = []
    prev = None
    for k, n in enumerate(targets):
        out = os.path.join(case.work, f"{tag}-{variant}-{k}.msh")
        if variant == "uniform" or prev is None:
            start = out if variant == "uniform" else os.path.join(case.work, f"{tag}-start.msh")
            rep = case.uniform_for(start, n)
            if variant != "uniform":
                prev = start
        for p in range(passes if variant != "uniform" else 0):
            src = prev + ".f.msh"
            case.sample(prev, field, src)
            out = os.path.join(case.work, f"{tag}-{variant}-{k}-{p}.msh")
            rep = case.adapt(src, out, n, 1 if variant == "iso" else 10)
            prev = out
        l2, linf = case.error(out, field)
        mu, eta = metric_quality(rep, case.d)
        rows.append((rep["counts"]["nodes"], l2, linf, mu, eta))
    return rows


def rates(rows):
    """-d log(L2) / d log(N) between successive rows (None for the first)."""
    out = [None]
    for a, b in zip(rows, rows[1:]):
        out.append(-np.log(b[1] / a[1]) / np.log(b[0] / a[0]))
    return out


def error_at(rows, nodes):
    """L2 of a sequence at `nodes`, interpolated (or extrapolated from the nearest pair) in log-log."""
    N = np.log([r[0] for r in rows])
    E = np.log([r[1] for r in rows])
    i = int(np.clip(np.searchsorted(N, np.log(nodes)), 1, len(N) - 1))
    t = (np.log(nodes) - N[i - 1]) / (N[i] - N[i - 1])
    return float(np.exp(E[i - 1] + t * (E[i] - E[i - 1])))


def slope(rows):
    """Least-squares slope of log(L2) against log(N) over a sequence."""
    return float(np.polyfit(np.log([r[0] for r in rows]), np.log([r[1] for r in rows]), 1)[0])
