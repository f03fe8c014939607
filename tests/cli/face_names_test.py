#!/usr/bin/python3
"""STEP face names and colours into every output (issue 17, "faces you can find"), on
models/named_faces.step (tools/models/make_models.cpp: two cubes side by side, LEFT x 0..10 and
RIGHT x 10..20; faces named "fixed" (red) at x = 0, "load face" (blue) at x = 20, "top" on both
tops z = 10; LEFT's bottom grey without a name; RIGHT's part green):
- info --faces --json: the names and colours on the faces where the file puts them (found by
  their centroids, after fragmenting), the part colour on RIGHT's solid and on none of its faces;
  the same without fragmenting;
- MSH 4.1 read by Gmsh: physical groups "fixed", "top" (both tops), "load_face" beside FACE<n>,
  on the faces info names; MSH 2.2 read by meshio: the named groups' triangles are those of their
  faces;
- INP (volume and surface): *NSET and *SURFACE S_<name> / *ELSET <name> equal to the union of
  the FACE<n> sets of the named faces;
- VTU read by meshio: FieldData region:<part> and face:<name> decode "region" and "face";
- UNV: a group per name holding the elements of its faces;
- bracket.step (no face names): no group beyond FACE<n> and the part.
usage: face_names_test.py CLI MODELS_DIR"""
import json, os, re, sys, tempfile

import clitest
from clitest import check, failures as fails

cli, models = sys.argv[1], sys.argv[2]
named = os.path.join(models, "named_faces.step")


def run(*args):
    r = clitest.run(cli, *args, timeout=300)
    assert r.returncode == 0, r.stderr
    return r.stdout


def face_at(faces, axis, value):
    return [f["id"] for f in faces if abs(f["centroid"][axis] - value) < 1e-6]


for extra in ([], ["--no-fragment"]):
    j = json.loads(run("info", named, "--faces", "--json", *extra))
    faces, solids = j["face_list"], j["prepared"]["solid_list"]
    tag = f" ({' '.join(extra) or 'fragmented'})"
    by_name = {}
    for f in faces:
        if "name" in f: by_name.setdefault(f["name"], []).append(f["id"])
    fixed, load = face_at(faces, 0, 0), face_at(faces, 0, 20)
    tops = [f["id"] for f in faces if abs(f["centroid"][2] - 10) < 1e-6]
    bottom = [f["id"] for f in faces if abs(f["centroid"][2]) < 1e-6 and f["centroid"][0] < 10]
    check(by_name == {"fixed": fixed, "top": tops, "load face": load} and len(tops) == 2,
          f"names on their faces{tag}: {by_name}")
    colors = {f["id"]: f["color"] for f in faces if "color" in f}
    check(colors == {fixed[0]: "#ff0000", load[0]: "#0000ff", bottom[0]: "#808080"}, f"face colours{tag}: {colors}")
    check([s.get("color") for s in solids] == [None, "#00ff00"], f"part colour on RIGHT only{tag}")
    text = run("info", named, "--faces", *extra)
    check('name "load face"  colour #0000ff' in text, f"the text table names and colours a face{tag}")

j = json.loads(run("info", named, "--faces", "--json"))
faces = j["face_list"]
want = {"fixed": face_at(faces, 0, 0), "top": [f["id"] for f in faces if abs(f["centroid"][2] - 10) < 1e-6],
        "load_face": face_at(faces, 0, 20)}

with tempfile.TemporaryDirectory() as tmp:
    out = lambda name: os.path.join(tmp, name)
    run("mesh", named, "-o", out("n.msh"), "-q")
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(out("n.msh"))
    groups = {gmsh.model.getPhysicalName(d, t): (d, t) for d, t in gmsh.model.getPhysicalGroups()}
    got = {n: sorted(gmsh.model.getEntitiesForPhysicalGroup(*groups[n]).tolist()) for n in want if n in groups}
    check(got == want, f"MSH 4.1 (Gmsh): named groups on their faces {got}")
    check({"LEFT", "RIGHT"} <= set(groups) and all(f"FACE{i}" in groups for i in range(1, len(faces) + 1)),
          "MSH 4.1: the parts and every FACE<n> beside them")
    gmsh.finalize()

    import meshio
    run("mesh", named, "-o", out("n22.msh"), "--msh-version", "22", "-q")
    m = meshio.read(out("n22.msh"))
    tags = {n: int(v[0]) for n, v in m.field_data.items()}
    tri = [(b.data, m.cell_data["gmsh:physical"][i]) for i, b in enumerate(m.cells) if b.type == "triangle"]
    def triangles(tag_set):
        return sorted(tuple(sorted(c)) for data, phys in tri for c, p in zip(data, phys) if p in tag_set)
    ok = all(triangles({tags[n]}) == triangles({tags[f"FACE{i}"] for i in want[n]}) and triangles({tags[n]})
             for n in want)
    check(ok, "MSH 2.2 (meshio): each named group holds the triangles of its faces")

    def inp_sets(path):
        sets, key = {}, None
        for line in open(path):
            if line.startswith("**"): continue
            if line.startswith("*"):
                mt = re.match(r"\*(NSET|ELSET|SURFACE), (?:NSET|ELSET|NAME)=([^,\s]+)", line)
                key = (mt.group(1), mt.group(2)) if mt and "GENERATE" not in line else None
                if key: sets[key] = set()
                continue
            if key: sets[key].update(x.strip() for x in (line.split(",") if key[0] != "SURFACE" else [line.strip()]) if x.strip())
        return sets

    run("mesh", named, "-o", out("n.inp"), "-q")
    s = inp_sets(out("n.inp"))
    union = lambda kind, prefix, ids: set().union(*(s[(kind, f"{prefix}FACE{i}")] for i in ids))
    check(all(s.get(("NSET", n)) == union("NSET", "", ids) and s.get(("SURFACE", "S_" + n)) == union("SURFACE", "S_", ids)
              for n, ids in want.items()), "INP (volume): NSET <name> and SURFACE S_<name> of the named faces")
    run("mesh", named, "--dim", "2", "-o", out("n2.inp"), "-q")
    s = inp_sets(out("n2.inp"))
    check(all(s.get(("ELSET", n)) == union("ELSET", "", ids) and s.get(("NSET", n)) == union("NSET", "", ids)
              for n, ids in want.items()), "INP (surface): ELSET and NSET <name> of the named faces")

    run("mesh", named, "-o", out("n.vtu"), "-q")
    m = meshio.read(out("n.vtu"))
    fd = {k: v.tolist() for k, v in m.field_data.items()}
    check(fd == {"region:LEFT": [1], "region:RIGHT": [2], **{"face:" + n: ids for n, ids in want.items()}},
          f"VTU (meshio): FieldData {fd}")

    run("mesh", named, "-o", out("n.unv"), "-q")
    lines = open(out("n.unv")).read().split("\n")
    names = [l.strip() for l in lines]
    check(all(n in names for n in want) and "FACE1" in names, "UNV: a group per face name beside FACE<n>")

    run("mesh", os.path.join(models, "bracket.step"), "-o", out("b.msh"), "-q")
    header = open(out("b.msh")).read().split("$EndPhysicalNames")[0]
    check(int(header.split("$PhysicalNames\n")[1].split("\n")[0]) == 14 + 1, "bracket: FACE1..14 and the part only")

print(f"{len(fails)} failed" if fails else "all passed")
sys.exit(1 if fails else 0)
