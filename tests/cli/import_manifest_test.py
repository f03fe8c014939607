#!/usr/bin/python3
"""Import test: `anisomesh info --json` on every model of ../shared/models equals MANIFEST.json
(what OCCT reads with no healing): counts exactly, volume and area within 1e-3 relative.
usage: import_manifest_test.py CLI MODELS_DIR"""
import json, os, subprocess, sys

cli, models = sys.argv[1], sys.argv[2]
manifest = json.load(open(os.path.join(models, "MANIFEST.json")))
# Conformal preparation: for the multi-solid models, the faces bounding one solid only must
# have the area of the outer boundary of the union (shared/tools/assemblies.json).
asm_path = os.path.join(models, "..", "tools", "assemblies.json")
assemblies = {a["file"]: a for a in json.load(open(asm_path))} if os.path.exists(asm_path) else {}
failed = []
for m in manifest:
    if "error" in m:
        continue
    path = os.path.join(models, m["file"])
    try:
        p = subprocess.run([cli, "info", "--json", path], capture_output=True, text=True, timeout=300)
    except subprocess.TimeoutExpired:
        failed.append(f"{m['file']}: timeout"); continue
    if p.returncode != 0:
        failed.append(f"{m['file']}: exit {p.returncode}: {p.stderr.strip()[:200]}"); continue
    j = json.loads(p.stdout)
    why = [f"{k} {j[k]} != {m[k]}" for k in ("solids", "shells", "faces", "edges", "vertices") if j[k] != m[k]]
    close = lambda x, ref: abs(x - ref) <= 1e-3 * max(abs(ref), 1e-300) or (ref == 0 and abs(x) < 1e-12)
    if not close(j["volume"], m["volume"]):
        why.append(f"volume {j['volume']:.9g} != {m['volume']:.9g}")
    # The manifest's area is OCCT's integral of the shape, or (where its note says so, e.g. a
    # shell listing a face twice) the area of the distinct faces: info reports both.
    if not (close(j["area"], m["area"]) or close(j.get("unique_face_area", float("nan")), m["area"])):
        why.append(f"area {j['area']:.9g} (distinct faces {j.get('unique_face_area')}) != {m['area']:.9g}")
    prep = j.get("prepared", {})
    if m["solids"] > 0 and prep.get("solids", 0) == 0:
        why.append("preparation lost the solids")
    a = assemblies.get(m["file"])
    if a:
        if prep.get("solids") != a["solids"]:
            why.append(f"prepared solids {prep.get('solids')} != {a['solids']}")
        if abs(prep.get("exposed_area", 0) - a["outer_area"]) > 1e-3 * a["outer_area"]:
            why.append(f"prepared exposed area {prep.get('exposed_area')} != outer area {a['outer_area']} (not conformal)")
        if abs(prep.get("volume", 0) - a["union_volume"]) > 1e-3 * a["union_volume"]:
            why.append(f"prepared volume {prep.get('volume')} != union volume {a['union_volume']}")
    if why:
        failed.append(f"{m['file']}: " + "; ".join(why))
    else:
        print(f"ok {m['file']}", flush=True)
for f in failed:
    print("FAIL", f)
n = sum(1 for m in manifest if "error" not in m)
print(f"{n - len(failed)} passed, {len(failed)} failed")
sys.exit(1 if failed else 0)
