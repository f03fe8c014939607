#!/usr/bin/python3
"""Overlapping parts (issue 20, --overlaps): models/overlap2.step holds two 10 mm cubes, BOX_A at
the origin and BOX_B at (5, 0, 0), overlapping in a 5 x 10 x 10 region (volume 500).
- info --json: one overlap, volume 500 (1e-6 relative), both names, kept in BOX_A (equal
  volumes: the part first in the file keeps the common region); BOX_A 1000, BOX_B 500 after.
- mesh --dim 3 (merge, the default): exit 0, status ok, the report's model block lists the
  overlap and stderr warns once; the referee finds no inverted tetrahedron, total volume 1500
  (1 %), exposed area of the tetrahedra 800 = the union's outer area (1 %: conformal), two
  regions of volumes 1000 and 500.
- --overlaps error: exit 2 naming both parts and the volume.
- --overlaps keep: exit 0 and the same mesh as --no-fragment (the behaviour before merge).
usage: overlaps_test.py CLI MODELS_DIR SHARED_DIR"""
import json, os, sys, tempfile
import functools

import clitest
from clitest import check, failures as fails

import meshio
import numpy as np

cli, models, shared = sys.argv[1], sys.argv[2], sys.argv[3]
sys.path.insert(0, os.path.join(shared, "tools"))
import meshq  # the referee

model = os.path.join(models, "overlap2.step")
t = tempfile.mkdtemp()
run = functools.partial(clitest.run, cli)


def exposed_area_and_regions(path):
    m = meshio.read(path)
    P = np.asarray(m.points, float)
    T, vol = [], {}
    for i, cb in enumerate(m.cells):
        if cb.type != "tetra": continue
        c = np.asarray(cb.data)
        T.append(c)
        tags = np.asarray(m.cell_data["gmsh:geometrical"][i])
        a, b, cc, d = (P[c[:, k]] for k in range(4))
        v = np.abs(np.einsum("ij,ij->i", np.cross(b - a, cc - a), d - a)) / 6
        for tag in np.unique(tags): vol[int(tag)] = vol.get(int(tag), 0) + float(v[tags == tag].sum())
    T = np.vstack(T)
    F = np.sort(np.vstack([T[:, [1, 2, 3]], T[:, [0, 2, 3]], T[:, [0, 1, 3]], T[:, [0, 1, 2]]]), axis=1)
    u, cnt = np.unique(F, axis=0, return_counts=True)
    ex = u[cnt == 1]
    area = 0.5 * np.linalg.norm(np.cross(P[ex[:, 1]] - P[ex[:, 0]], P[ex[:, 2]] - P[ex[:, 0]]), axis=1).sum()
    return float(area), vol


# info
p = run("info", "--json", model)
check(p.returncode == 0, f"info exits 0 ({p.returncode}: {p.stderr.strip()[-200:]})")
j = json.loads(p.stdout) if p.returncode == 0 else {"prepared": {"overlaps": [], "solid_list": []}}
ov = j["prepared"]["overlaps"]
check(len(ov) == 1, f"one overlap reported ({len(ov)})")
if ov:
    o = ov[0]
    check(abs(o["volume"] - 500) <= 1e-6 * 500, f"overlap volume 500 ({o['volume']})")
    check({o["name_a"], o["name_b"]} == {"BOX_A", "BOX_B"}, f"both part names ({o['name_a']}, {o['name_b']})")
    keeper = o["name_a"] if o["assigned_to"] == o["a"] else o["name_b"] if o["assigned_to"] == o["b"] else None
    check(keeper == "BOX_A", f"equal volumes: the first part keeps the common region ({keeper})")
vols = {s["name"]: s["volume"] for s in j["prepared"]["solid_list"]}
check(len(j["prepared"]["solid_list"]) == 2, f"two solids after preparation ({len(j['prepared']['solid_list'])})")
check(abs(vols.get("BOX_A", 0) - 1000) < 1e-6 * 1000 and abs(vols.get("BOX_B", 0) - 500) < 1e-6 * 500,
      f"BOX_A keeps 1000, BOX_B 500 ({vols})")
check(j["prepared"]["shared_faces"] >= 1, f"the parts share their interface ({j['prepared']['shared_faces']})")
p = run("info", model)
check("overlap, volume 500" in p.stdout, "info's text names the overlap")

# mesh, merge (the default)
opts = ["--dim", "3", "--hmax-rel", "0.1", "--anisotropy", "1"]
out, rep = os.path.join(t, "merge.msh"), os.path.join(t, "merge.json")
p = run("mesh", model, "-o", out, "--report", rep, *opts)
check(p.returncode == 0, f"merge: exit 0 ({p.returncode}: {p.stderr.strip()[-200:]})")
if p.returncode == 0:
    r = json.load(open(rep))
    check(r["status"] == "ok", f"merge: status ok ({r['status']})")
    check(len(r.get("model", {}).get("overlaps", [])) == 1, "merge: the report's model block lists the overlap")
    check(r["options"].get("overlaps") == "merge", "merge: the report's options name the policy")
    warned = [l for l in p.stderr.splitlines() if "overlapping part pair" in l]
    check(len(warned) == 1, f"merge: one warning line on the overlaps ({warned})")
    q = meshq.stats(out)
    check(q.get("tets", 0) > 0 and q["inverted"] == 0, f"merge: tetrahedra, none inverted ({q.get('inverted')})")
    check(abs(q["volume"] - 1500) <= 0.01 * 1500, f"merge: volume 1500 ({q['volume']})")
    area, regions = exposed_area_and_regions(out)
    check(abs(area - 800) <= 0.01 * 800, f"merge: exposed area 800, conformal ({area:.3f})")
    rv = sorted(round(v) for v in regions.values())
    check(rv == [500, 1000], f"merge: two regions, 500 and 1000 ({rv})")

# error
p = run("mesh", model, "-o", os.path.join(t, "error.msh"), "--overlaps", "error", *opts)
check(p.returncode == 2, f"error: exit 2 ({p.returncode})")
check("BOX_A" in p.stderr and "BOX_B" in p.stderr and "500" in p.stderr, f"error: names the pair and the volume ({p.stderr.strip()})")
check(not os.path.exists(os.path.join(t, "error.msh")), "error: no mesh written")
p = run("info", model, "--overlaps", "error")
check(p.returncode == 2, f"error: info exits 2 too ({p.returncode})")

# keep = the behaviour before merge: the solids left unfragmented, as with --no-fragment
keep, nofrag = os.path.join(t, "keep.msh"), os.path.join(t, "nofrag.msh")
p = run("mesh", model, "-o", keep, "--overlaps", "keep", *opts)
check(p.returncode == 0, f"keep: exit 0 ({p.returncode})")
check("not fragmented" in p.stderr, "keep: warns that the solids are not fragmented")
p2 = run("mesh", model, "-o", nofrag, "--no-fragment", *opts)
check(p.returncode == 0 and p2.returncode == 0 and open(keep, "rb").read() == open(nofrag, "rb").read(),
      "keep: the same mesh as --no-fragment")
if p.returncode == 0:
    q = meshq.stats(keep)
    check(abs(q["volume"] - 2000) <= 0.01 * 2000, f"keep: two whole cubes, volume 2000 ({q['volume']})")

print(f"{'FAILED' if fails else 'passed'}: {len(fails)} failure(s)")
sys.exit(1 if fails else 0)
