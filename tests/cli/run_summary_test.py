#!/usr/bin/python3
"""A run that speaks (issue 17): the summary on success, --progress, and the errors a new user meets.
- mesh bracket (3D) with --report: exit 0; the summary's element and node counts equal the report's
  counts and the tetrahedra/triangles meshio reads from the written file; its quality min/mean equal
  the report's quality.elements (the Euclidean mean ratio) and agree with quality.volume.mean_ratio;
  the histogram's bins add up to the tetrahedra; the output line names the file and its size; -q
  prints nothing.
- --progress on bracket: at most 40 lines (1,560 before), every phase one token (no spaces), percent
  lines parsed by the FreeCAD dialog's pattern; as1-tu-203 (18 parts, ~10 s) under 300 lines (15,769).
- overlap2.step: the summary warns of the overlapping parts and says where the common region went.
- a part written in inches: info, info --json and the summary name the file's unit (lengths in mm).
- -o DIR: exit 2 "is a directory"; --quad on a solid: --dim 2 implied and said (quads written, no
  tetrahedra); --quad --dim 3: exit 2 naming the fix.
usage: run_summary_test.py CLI MODELS_DIR SHARED_DIR"""
import json, os, re, subprocess, sys, tempfile

import meshio

cli, models, shared = sys.argv[1], sys.argv[2], sys.argv[3]
bracket = os.path.join(models, "bracket.step")
t = tempfile.mkdtemp()
fails = []
FREECAD_PROGRESS = re.compile(r"^progress: (\S+) (\d+)% ?(.*)$")  # tools/freecad/anisomesh_freecad.py


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond: fails.append(what)


def run(*args, timeout=120):
    return subprocess.run([cli, *args], capture_output=True, text=True, timeout=timeout)


def summary_number(err, pattern):
    m = re.search(pattern, err)
    return float(m.group(1)) if m else None


# --- the summary, against the report and the written mesh
out, rep = os.path.join(t, "b.msh"), os.path.join(t, "b.json")
r = run("mesh", bracket, "-o", out, "--report", rep)
check(r.returncode == 0, f"bracket meshes (exit {r.returncode}: {r.stderr[-300:]})")
report = json.load(open(rep))
counts, q = report["counts"], report["quality"]["elements"]
err = r.stderr
print(err)
m = meshio.read(out)
tets = sum(len(c.data) for c in m.cells if c.type == "tetra")
tris = sum(len(c.data) for c in m.cells if c.type == "triangle")
check(summary_number(err, r"(\d+) tetrahedra") == counts["tetrahedra"] == tets > 0,
      f"tetrahedra: summary, report {counts['tetrahedra']} and file {tets} agree")
check(summary_number(err, r"(\d+) boundary triangles") == counts["triangles"] == tris > 0,
      f"boundary triangles: summary, report {counts['triangles']} and file {tris} agree")
check(summary_number(err, r"(\d+) nodes") == counts["nodes"] == len(m.points), "nodes agree")
check(summary_number(err, r"(\d+) parts?") == len(report["model"]["solid_list"]) == 1, "1 part")
check(abs(summary_number(err, r"min (\d\.\d+), mean") - q["min"]) < 1e-3, "summary min = report min")
check(abs(summary_number(err, r"mean (\d\.\d+);") - q["mean"]) < 1e-3, "summary mean = report mean")
vol = report["quality"]["volume"]["mean_ratio"]
check(abs(q["min"] - vol["min"]) < 1e-6 and abs(q["mean"] - vol["mean"]) < 1e-6,
      "quality.elements agrees with quality.volume.mean_ratio")
check(abs(summary_number(err, r"smallest dihedral angle (\d+\.\d) deg") - q["dihedral_min"]) < 0.06, "dihedral")
bins = [int(b) for b in re.findall(r"^anisomesh:\s+\d\.\d-\d\.\d\s+(\d+) #+$", err, re.M)]
check(sum(bins) == tets == sum(q["histogram"]["bins"]), f"histogram lines add up to the tetrahedra ({sum(bins)})")
check(re.search(r"wrote .*b\.msh \((\d+\.\d) (kB|MB)\) in \d+\.\d\d s", err) is not None, "output path and size")
check(report["status"] == "ok" and "warning" not in err, "no warning on a clean run")
r = run("-q", "mesh", bracket, "-o", out)
check(r.returncode == 0 and r.stderr == "", "-q: nothing on stderr")

# --- progress
r = run("--progress", "mesh", bracket, "-o", out)
lines = [l for l in r.stderr.splitlines() if l.startswith("progress:")]
check(r.returncode == 0 and 0 < len(lines) <= 40, f"bracket --progress: {len(lines)} lines (at most 40)")
check(all(len(l.split()) >= 2 and (l.split()[2:3] in ([], ["done"]) or FREECAD_PROGRESS.match(l)) for l in lines),
      "every progress line: one-token phase, then a percent (the FreeCAD pattern), done, or nothing")
check(not any("Delaunay" in l for l in lines), "nested phases (Delaunay 3D) folded into their parent")
big = os.path.join(shared, "models", "as1-tu-203.stp")
if os.path.exists(big):
    r = run("--progress", "mesh", big, "-o", os.path.join(t, "a.msh"), timeout=300)
    n = sum(l.startswith("progress:") for l in r.stderr.splitlines())
    check(r.returncode == 0 and n < 300, f"as1-tu-203 --progress: {n} lines (under 300)")
    check("18 parts" in r.stderr, "as1-tu-203 summary: 18 parts")

# --- warnings in the summary
r = run("mesh", os.path.join(models, "overlap2.step"), "-o", os.path.join(t, "o.msh"))
check(r.returncode == 0 and re.search(r"warning: overlapping parts: part 1 'BOX_A' and part 2 'BOX_B' .*merged.*in part 1",
                                      r.stderr) is not None, "overlap2: the summary names the merged overlap")

# thin walls: the faces refined and the smallest size asked, as the report has them
thin = os.path.join(shared, "models", "periodic_u_cst.step")
if os.path.exists(thin):
    rep = os.path.join(t, "pu.json")
    r = run("mesh", thin, "-o", os.path.join(t, "pu.msh"), "--hmax-rel", "0.5", "--curvature-ratio", "0.15",
            "--report", rep)
    px = json.load(open(rep))["proximity"] if r.returncode == 0 else {}
    refined = px.get("refined", [])
    m = re.search(r"thin walls: .*element size down to ([0-9.e+-]+) on face\(s\) ([0-9, ]+)\)", r.stderr)
    check(px.get("rounds", 0) >= 1 and refined and m is not None
          and abs(float(m.group(1)) - min(e["size"] for e in refined)) < 1e-5 * float(m.group(1))
          and [int(x) for x in m.group(2).split(",")] == [e["face"] for e in refined],
          f"periodic_u_cst: the thin-wall warning names the faces and size of the report ({r.stderr[-300:]})")

# --- units: the bracket written in inches is read in mm and said so (info, info --json, mesh)
text = open(bracket).read()
mm_unit = re.search(r"#(\d+) = \( LENGTH_UNIT\(\) NAMED_UNIT\(\*\) SI_UNIT\(\.MILLI\.,\.METRE\.\) \);", text)
check(mm_unit is not None, "bracket.step declares millimetres")
if mm_unit:
    inch = os.path.join(t, "bracket_inch.step")
    open(inch, "w").write(text.replace(mm_unit.group(0), (
        f"#{mm_unit.group(1)} = ( CONVERSION_BASED_UNIT('INCH',#990001) LENGTH_UNIT() NAMED_UNIT(#990002) );\n"
        "#990001 = LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#990003);\n"
        "#990002 = DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n"
        "#990003 = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );")))
    mm_info, in_info = json.loads(run("info", bracket, "--json").stdout), json.loads(run("info", inch, "--json").stdout)
    check(mm_info["file_unit"] == "millimetre" and in_info["file_unit"] == "inch"
          and abs(in_info["volume"] / mm_info["volume"] - 25.4 ** 3) < 1e-6 * 25.4 ** 3,
          f"info --json: file_unit millimetre / inch, the inch part 25.4^3 times the volume ({in_info.get('file_unit')})")
    check("lengths in mm, converted from inch" in run("info", inch).stdout, "info names the file's unit")
    r = run("mesh", inch, "-o", os.path.join(t, "bi.msh"), "--size", "50")
    check(r.returncode == 0 and "(lengths in mm, converted from inch)" in r.stderr, "mesh: the summary names the file's unit")
    r = run("mesh", bracket, "-o", os.path.join(t, "bm.msh"), "--size", "2")
    check(r.returncode == 0 and "(lengths in mm)" in r.stderr, "mesh: a millimetre file says mm only")

# --- errors a new user meets
r = run("mesh", bracket, "-o", t)
check(r.returncode == 2 and "is a directory" in r.stderr and len(r.stderr.splitlines()) == 1,
      f"-o DIR: exit 2, one line 'is a directory' ({r.stderr.strip()})")
q2 = os.path.join(t, "q.msh")
r = run("mesh", bracket, "-o", q2, "--quad")
mq = meshio.read(q2) if r.returncode == 0 else None
check(r.returncode == 0 and "--dim 2 implied" in r.stderr and "surface mesh bug" not in r.stderr,
      f"--quad on a solid: --dim 2 implied and said (exit {r.returncode})")
check(mq is not None and any(c.type == "quad" for c in mq.cells) and not any(c.type == "tetra" for c in mq.cells),
      "--quad on a solid: quads written, no tetrahedra")
r = run("mesh", bracket, "-o", q2, "--quad", "--dim", "3")
check(r.returncode == 2 and "--quad --dim 2" in r.stderr, f"--quad --dim 3: exit 2 with the fix ({r.stderr.strip()})")

print(f"{len(fails)} failed" if fails else "all passed")
sys.exit(1 if fails else 0)
