#!/bin/bash
# The macro's dialog in the FreeCAD GUI under Xvfb (issue 17), through freecad_dialog.py:
# the values it shows are the CLI's defaults (`anisomesh mesh --help`: max/min size = the
# relative defaults × the selection's bounding-box diagonal, elements per circle, order; a
# volume mesh of the solids; no quads) and an untouched dialog sends no option; every field
# has a tooltip naming its CLI option; "Mesh" makes one FemMeshObject linked to the selection
# (a Part::Compound of Plate and Pin), groups named after the objects, the summary line and
# the overlap warning (with the objects' names) shown in the dialog. Screenshots before and
# after the run are kept in the test's log folder (build/Testing/freecad_dialog/), their
# paths printed. Skipped (exit 77) with a message where freecad or xvfb-run is missing.
# usage: freecad_dialog_test.sh CLI PROJECT_DIR LOG_DIR
cli=$1; proj=$2; log=$3
for tool in freecad xvfb-run; do
  command -v $tool > /dev/null || { echo "SKIP: $tool not installed (packages freecad, xvfb): the dialog is not tested"; exit 77; }
done
mkdir -p "$log"; rm -f "$log"/dialog*.png "$log/dialog.json"
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
export HOME=$t   # FreeCAD writes its settings under $HOME
(cd "$t" && QTWEBENGINE_DISABLE_SANDBOX=1 ANISOMESH="$cli" ANISOMESH_MACRO_DIR="$proj/tools/freecad" \
   ANISOMESH_TEST_OUT="$log" timeout 300 xvfb-run -a freecad "$proj/tests/freecad/freecad_dialog.py" > "$log/freecad.log" 2>&1)
[ -f "$log/dialog.json" ] || { echo "FAIL the dialog script wrote nothing: $(tail -5 "$log/freecad.log")"; exit 1; }
echo "screenshots: $log/dialog_before.png $log/dialog_after.png"
"$cli" mesh --help > "$t/help.txt" || { echo "FAIL $cli mesh --help"; exit 1; }
/usr/bin/python3 - "$log/dialog.json" "$t/help.txt" <<'PY'
import json, os, re, sys
r = json.load(open(sys.argv[1]))
assert "error" not in r, r["error"]
print(json.dumps({k: r[k] for k in ("shown", "untouched_options", "summary", "warnings_text", "part", "meshes")}))
helptext = open(sys.argv[2]).read()
default = lambda opt: re.search(re.escape(opt) + r"\b.*\(default ([^)\s]+)\)", helptext).group(1)
s, d = r["shown"], r["diagonal"]
assert abs(s["hmax"] - float(default("--hmax-rel")) * d) <= 1e-5, (s["hmax"], d)
assert abs(s["hmin"] - float(default("--hmin-rel")) * d) <= 1e-5, (s["hmin"], d)
assert s["elements_per_circle"] == int(float(default("--elements-per-circle"))), s
assert s["order"] == int(default("--order")) and s["size"] == 0.0 and not s["quad"] and not s["surface"], s
assert r["untouched_options"] == [], r["untouched_options"]
assert all(re.search(r"--[a-z]", tip) for tip in r["tooltips"].values()), r["tooltips"]
for label in ("Element size", "Max element size", "Min element size", "Elements per circle", "Element order"):
    assert label in r["labels"], (label, r["labels"])
assert r["meshes"] == 1 and r["part"] == "AnisoMeshParts" and r["in_analysis"], r
assert "Plate" in r["groups"] and "Pin" in r["groups"] and "Plate_Face7" in r["groups"] and "Pin_Face3" in r["groups"], r["groups"]
assert re.match(r"AnisoMesh of Plate\+Pin: \d+ nodes, \d+ tetrahedra, .* 2 warnings$", r["summary"]), r["summary"]
assert "'Plate' and part 2 'Pin'" in r["warnings_text"] and "SOLID" not in r["warnings_text"], r["warnings_text"]
for shot in ("screenshot_before", "screenshot_after"):
    assert os.path.getsize(r[shot]) > 1000, r[shot]
print("ok dialog")
PY
