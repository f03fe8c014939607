"""tools/bench/census.py on a folder made at test time: two sample models, a copy of one whose
manifest volume is 5 % off (meshes ok, must fail the volume criterion) and a truncated STEP file
(must be reported failed without stopping the run). MANIFEST.json is computed from
`anisomesh info --json`. Checks the lines, the summary, the JSONL records, the exit code (1 when a
model fails, 0 when all pass), a run killed by the time limit, and the one-line refusal without
the shared folder.

usage: census_tool_test.py ANISOMESH MODELS_DIR
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

CLI, MODELS = sys.argv[1], sys.argv[2]
CENSUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "bench", "census.py")
EXTRA = "--hmax-rel 0.1"
failures = []
checks = 0


def check(name, ok, detail=""):
    global checks
    checks += 1
    if not ok:
        failures.append(f"{name}: {detail}")


def census(folder, *args):
    p = subprocess.run(["/usr/bin/python3", CENSUS, "--cli", CLI, "--dir", folder, "--extra", EXTRA, *args],
                       capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout.splitlines(), p.stderr


def line_of(lines, name):
    found = [x for x in lines if x.startswith(name + " ")]
    return found[0] if len(found) == 1 else ""


def info(path):
    p = subprocess.run([CLI, "info", path, "--json"], capture_output=True, text=True, timeout=120)
    j = json.loads(p.stdout)
    return {"solids": j["solids"], "volume": j["volume"], "area": j["area"]}


folder = tempfile.mkdtemp(prefix="census-test-")
try:
    manifest = []
    for name in ("cantilever.step", "plate.step"):
        shutil.copy(os.path.join(MODELS, name), folder)
        manifest.append({"file": name, **info(os.path.join(folder, name))})
    shutil.copy(os.path.join(MODELS, "cantilever.step"), os.path.join(folder, "offvolume.step"))
    manifest.append({**manifest[0], "file": "offvolume.step", "volume": 1.05 * manifest[0]["volume"]})
    with open(os.path.join(MODELS, "cantilever.step"), "rb") as f:
        data = f.read()
    with open(os.path.join(folder, "truncated.step"), "wb") as f:
        f.write(data[:len(data) // 2])
    manifest.insert(1, {**manifest[0], "file": "truncated.step"})  # before plate: the run must go on
    with open(os.path.join(folder, "MANIFEST.json"), "w") as f:
        json.dump(manifest, f)

    # 1. The whole folder, Gmsh beside: two pass, the truncated file and the wrong volume fail.
    jsonl = os.path.join(folder, "census.jsonl")
    rc, lines, err = census(folder, "--gmsh", "--jsonl", jsonl)
    check("exit code with failures", rc == 1, f"{rc}; {err[-300:]}")
    for name in ("cantilever.step", "plate.step"):
        line = line_of(lines, name)
        check(f"{name} line", " 3D  ok/0 " in line and " tets eta " in line and line.count(" PASS") == 1
              and "| gmsh ok/0 " in line, line or lines)
    line = line_of(lines, "truncated.step")
    check("truncated reported failed", "failed/2" in line and " FAIL" in line and "truncated" in line.split("first:")[-1],
          line or lines)
    line = line_of(lines, "offvolume.step")
    check("wrong volume fails with status ok", " ok/0 " in line and "volume off by -4.76%" in line, line or lines)
    check("one line per model, in manifest order",
          [x.split()[0] for x in lines[1:5]] ==
          ["cantilever.step", "truncated.step", "plate.step", "offvolume.step"], lines)
    check("summary", "anisomesh: passed 2/4 (0 degraded); failed 1, ok 3;" in "\n".join(lines)
          and any(x.startswith("gmsh: passed ") for x in lines) and lines[-1].startswith("total "), lines[-3:])
    records = [json.loads(x) for x in open(jsonl)]
    check("jsonl records", [r["file"] for r in records] == [m["file"] for m in manifest], records)
    good = [r for r in records if r["file"] == "cantilever.step"][0]
    check("figures of a passing model",
          good["us"]["pass"] and good["us"]["tets"] > 0 and abs(good["us"]["vol_err"]) < 1e-3
          and abs(good["us"]["exposed_err"]) < 1e-3 and good["us"]["rss_mb"] > 1 and good["gmsh"]["tets"] > 0,
          good)

    p = subprocess.run(["/usr/bin/python3", CENSUS, "--table", jsonl], capture_output=True, text=True, timeout=60)
    rows = p.stdout.splitlines()
    check("markdown table", p.returncode == 0 and len(rows) == 2 + len(manifest)
          and rows[2].startswith("| cantilever.step | 3D | ok/0 | ") and " | yes | ok/0 | " in rows[2]
          and "| truncated.step | 3D | failed/2 |" in rows[3], rows)

    # 2. Only the good models: exit 0.
    rc, lines, err = census(folder, "--only", "cantilever.step,plate.step")
    check("exit code when all pass", rc == 0 and "anisomesh: passed 2/2 (0 degraded); ok 2;" in "\n".join(lines),
          f"{rc}: {lines}; {err[-300:]}")

    # 3. A time limit no run can meet: timeout, reported as such.
    rc, lines, err = census(folder, "--only", "plate.step", "--time-limit", "0.01")
    line = line_of(lines, "plate.step")
    check("timeout", rc == 1 and " timeout " in line and "killed after 0.01 s" in line, f"{rc}: {lines}")

    # 4. No shared folder: one clear line, exit 2.
    rc, lines, err = census(folder, "--shared", os.path.join(folder, "no-shared"))
    check("missing shared folder", rc == 2 and not lines and len(err.strip().splitlines()) == 1
          and "meshq.py" in err, f"{rc}: {lines} {err}")
finally:
    shutil.rmtree(folder, ignore_errors=True)

for f in failures:
    print("FAIL", f)
print(f"census_tool_test: {checks - len(failures)}/{checks} checks passed")
sys.exit(1 if failures else 0)
