#!/usr/bin/python3
"""info --faces (issue 17, "faces you can find"), against facts that do not come from the catalog:
- bracket: as many faces and edges as info --json counts; the face areas add up to the model's area
  (one solid: every face once); the edge lengths are positive except for degenerated edges; every
  face bounds solid 1 and carries its part name; the centroid lies in the face's box; an edge bounds two faces, or one
  cylinder twice (its seam); the text table
  has one row per face and per edge.
- as1-tu-203: 18 parts, every face with a type, an area > 0 and a centroid; the areas add up to
  unique_face_area, and counted once per solid they bound, to the area of every face occurrence.
usage: info_faces_test.py CLI MODELS_DIR SHARED_DIR"""
import json, os, subprocess, sys

cli, models, shared = sys.argv[1], sys.argv[2], sys.argv[3]
fails = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond: fails.append(what)


def info(path, *extra):
    r = subprocess.run([cli, "info", path, *extra], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    return r.stdout


def close(a, b, rel=1e-6):
    return abs(a - b) <= rel * max(abs(a), abs(b))


bracket = os.path.join(models, "bracket.step")
j = json.loads(info(bracket, "--faces", "--json"))
faces, edges, p = j["face_list"], j["edge_list"], j["prepared"]
check(len(faces) == p["faces"] == 14 and len(edges) == p["edges"], f"bracket: {len(faces)} faces, {len(edges)} edges")
check([f["id"] for f in faces] == list(range(1, len(faces) + 1)), "face ids 1..n")
check(close(sum(f["area"] for f in faces), j["area"]), "face areas add up to info --json's area")
check(all(e["length"] > 0 or e["type"] == "degenerated" for e in edges), "edge lengths > 0")
check(all(f["solids"] == [1] and f["part"] == p["solid_list"][0]["name"] for f in faces), "every face: solid 1, its part")
check(all(all(f["bbox"]["min"][k] - 1e-6 <= f["centroid"][k] <= f["bbox"]["max"][k] + 1e-6 for k in range(3))
          for f in faces if f["type"] == "plane"), "plane centroids inside their boxes")
check({f["type"] for f in faces} == {"plane", "cylinder"}, "bracket: planes and cylinders")
seams = [e for e in edges if len(e["faces"]) == 1]
check(all(len(e["faces"]) in (1, 2) for e in edges) and
      all(faces[e["faces"][0] - 1]["type"] == "cylinder" for e in seams),
      f"every bracket edge bounds two faces, or one cylinder twice (its seam: {len(seams)})")
text = info(bracket, "--faces")
rows = [l for l in text.splitlines() if l[:6].strip().isdigit()]
check(len(rows) == len(faces) + len(edges), f"text table: {len(rows)} rows")

big = os.path.join(shared, "models", "as1-tu-203.stp")
if os.path.exists(big):
    j = json.loads(info(big, "--faces", "--json"))
    faces, p = j["face_list"], j["prepared"]
    check(len(p["solid_list"]) == 18, f"as1-tu-203: {len(p['solid_list'])} parts")
    check(len(faces) == p["faces"] and all(f["type"] and f["area"] > 0 and len(f["centroid"]) == 3 for f in faces),
          f"as1-tu-203: {len(faces)} faces, each with type, area and centroid")
    check(close(sum(f["area"] for f in faces), p["unique_face_area"]), "areas add up to unique_face_area")
    check(close(sum(f["area"] * max(1, len(f["solids"])) for f in faces), p["area"], 1e-5),
          "areas times the solids they bound add up to the area of every occurrence")
    check(all(f["part"] for f in faces if f["solids"]), "every face of a solid names its part")

print(f"{len(fails)} failed" if fails else "all passed")
sys.exit(1 if fails else 0)
