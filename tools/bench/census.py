#!/usr/bin/python3
"""Census of a folder of CAD models: mesh each one, judge it with the referee, optionally beside Gmsh 4.8.

usage: census.py --cli BUILD/anisomesh --dir FOLDER [--extra "ARGS"] [--time-limit S] [--gmsh]
                 [--gmsh-time-limit S] [--gmsh-fragment] [--only a,b] [--jsonl OUT] [--shared DIR]
       census.py --table OUT.jsonl      (the results as a Markdown table, for docs/census.md)

The models are the files listed in FOLDER/MANIFEST.json when there is one, else every
.step/.stp/.iges/.igs/.brep file of the folder (then `anisomesh info --json` gives the solids, the
volume and the area the figures are compared with). Each model is meshed in 3D when it has solids,
else in 2D, killed after --time-limit seconds. One line per model as it finishes: run status and
exit code, wall time, peak RSS, element count, the referee's quality (SHARED/tools/meshq.py),
volume (2D: area) error against the manifest's union_volume (else volume), exposed-area error
against outer_area (faces used by one tetrahedron), PASS or FAIL with the reasons, and the first
warning or failure anisomesh printed or reported. --gmsh adds Gmsh's figures on the same line.

A model passes by the criteria of SHARED/tools/check_assemblies.py: exit 0, status ok or degraded,
3D: no inverted tet, mean ratio >= 0.80, min dihedral >= 2 deg, volume within 1 %, exposed area
within 1.5 %; 2D: area within 1 %, triangle mean ratio >= 0.90.
Exit 0 when every model passes with anisomesh, 1 otherwise, 2 on a usage error (e.g. no shared folder).
See docs/census.md."""
import argparse
import contextlib
import io
import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
CAD_EXTENSIONS = (".step", ".stp", ".iges", ".igs", ".brep")
CURVATURE_ELEMENTS = 24          # Gmsh: elements per 2 pi of curvature, as the acceptance scripts drive it
DEFAULT_HMAX_REL = 0.5           # anisomesh's --hmax-rel default (mesher/core/MeshOptions.h), used for Gmsh
# The acceptance criteria of check_assemblies.py.
ETA_MIN_3D, DIHEDRAL_MIN, VOLUME_TOL, EXPOSED_TOL = 0.80, 2.0, 0.01, 0.015
ETA_MIN_2D, AREA_TOL = 0.90, 0.01
MESSAGE_CHARS = 160
TIME = "/usr/bin/time"      # GNU time: the peak resident memory of a run


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cli", required=True, help="the anisomesh program")
    ap.add_argument("--dir", required=True, help="folder of CAD models (MANIFEST.json optional)")
    ap.add_argument("--extra", default="", help="options passed to `anisomesh mesh`")
    ap.add_argument("--time-limit", type=float, default=300, help="seconds per model before the run is killed")
    ap.add_argument("--gmsh", action="store_true", help="run Gmsh 4.8 on each model too")
    ap.add_argument("--gmsh-time-limit", type=float, help="Gmsh's limit (default: --time-limit)")
    ap.add_argument("--gmsh-fragment", action="store_true",
                    help="fragment Gmsh's solids first (conformal assemblies; the acceptance scripts do not)")
    ap.add_argument("--only", help="comma-separated file names")
    ap.add_argument("--jsonl", help="append one JSON record per model")
    ap.add_argument("--shared", default=os.path.join(ROOT, "..", "shared"), help="the shared folder (tools/meshq.py)")
    return ap.parse_args(argv)


def load_referee(shared):
    """The referee module SHARED/tools/meshq.py, or None when it is missing."""
    tools = os.path.join(os.path.abspath(shared), "tools")
    if not os.path.isfile(os.path.join(tools, "meshq.py")):
        return None
    sys.path.insert(0, tools)
    import meshq
    return meshq


# ---------------------------------------------------------------- running a process with a limit

def run_limited(cmd, limit, folder):
    """Runs cmd under /usr/bin/time in its own process group; after `limit` seconds the command is
    killed, then what is left of its group. Returns a dict: code (exit code, -signal when a signal ended it),
    timeout, wall_s, rss_mb (peak resident memory of the command; None when unknown), stdout, stderr.
    /usr/bin/time measures the peak because a child forked from this Python process would count
    the parent's memory in its own high-water mark."""
    out, err, rss = (os.path.join(folder, n) for n in ("stdout", "stderr", "rss"))
    timer = os.access(TIME, os.X_OK)
    remove(rss)
    with open(out, "w") as fo, open(err, "w") as fe:
        t0 = time.perf_counter()
        p = subprocess.Popen(([TIME, "-f", "maxrss %M", "-o", rss] if timer else []) + cmd,
                             stdin=subprocess.DEVNULL, stdout=fo, stderr=fe, start_new_session=True)
        timeout, pause = False, 0.005
        while p.poll() is None:
            if time.perf_counter() - t0 >= limit:
                timeout = True
                # The timer may not have started the command yet: then the whole group goes.
                if not timer or kill_children(p.pid) == 0:
                    os.killpg(p.pid, signal.SIGKILL)
                try:
                    p.wait(5)
                except subprocess.TimeoutExpired:
                    pass
                try:  # whatever is left of the group (the timer, the command's own children)
                    os.killpg(p.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
                break
            time.sleep(pause)
            pause = min(2 * pause, 0.05)
        wall = time.perf_counter() - t0
    code = p.wait()
    peak, measured = None, read_text(rss)
    m = re.search(r"maxrss (\d+)", measured)
    if m:
        peak = round(int(m.group(1)) / 1024, 1)
    m = re.search(r"terminated by signal (\d+)", measured)
    if m:
        code = -int(m.group(1))
    return {"code": code, "timeout": timeout, "wall_s": round(wall, 2), "rss_mb": peak,
            "stdout": read_text(out), "stderr": read_text(err)}


def kill_children(pid):
    """SIGKILL to the children of pid (the timed command under /usr/bin/time), so that the timer
    still writes the peak memory of a run that ran out of time."""
    try:
        with open(f"/proc/{pid}/task/{pid}/children") as f:
            children = [int(c) for c in f.read().split()]
    except OSError:
        children = []
    for c in children:
        try:
            os.kill(c, signal.SIGKILL)
        except ProcessLookupError:
            pass
    return len(children)


def read_text(path):
    try:
        with open(path, errors="replace") as f:
            return f.read()
    except OSError:
        return ""


def remove(*paths):
    """Removes the files a previous model's run left (so that a failing run is never judged by them)."""
    for p in paths:
        if os.path.exists(p):
            os.remove(p)


def run_status(run, reported):
    """The status word with the exit code: ok/0, degraded/0, failed/3, timeout, crash/139."""
    if run["timeout"]:
        return "timeout"
    if run["code"] < 0:
        return f"crash/{128 - run['code']}"
    if run["code"] != 0:
        return f"failed/{run['code']}"
    return f"{reported or '?'}/0"


# ---------------------------------------------------------------- the models of a folder

def model_list(args, workdir):
    """The entries to mesh: MANIFEST.json's, else one per CAD file with `anisomesh info --json`'s figures."""
    manifest = os.path.join(args.dir, "MANIFEST.json")
    if os.path.isfile(manifest):
        with open(manifest) as f:
            entries = json.load(f)
    else:
        names = sorted(n for n in os.listdir(args.dir) if n.lower().endswith(CAD_EXTENSIONS))
        entries = [{"file": n} for n in names]
    if args.only:
        wanted = set(args.only.split(","))
        entries = [e for e in entries if e["file"] in wanted]
    if not os.path.isfile(manifest):
        for e in entries:
            e.update(info_figures(args.cli, os.path.join(args.dir, e["file"]), args.time_limit, workdir))
    return entries


def info_figures(cli, path, limit, workdir):
    """solids, volume and area as `anisomesh info --json` reads them ({} when it cannot)."""
    run = run_limited([cli, "info", path, "--json"], limit, workdir)
    if run["code"] != 0 or run["timeout"]:
        return {}
    try:
        j = json.loads(run["stdout"])
    except ValueError:
        return {}
    counts = j.get("counts", j)
    return {k: v for k, v in (("solids", counts.get("solids")), ("volume", j.get("volume")),
                              ("area", j.get("area"))) if v is not None}


def dimension(entry):
    return 3 if (entry.get("solids") or 0) > 0 else 2


def hmax_rel(extra):
    """The relative size of the anisomesh run (--hmax-rel in --extra, else its default)."""
    words = shlex.split(extra)
    for i, w in enumerate(words):
        if w == "--hmax-rel" and i + 1 < len(words):
            return float(words[i + 1])
        if w.startswith("--hmax-rel="):
            return float(w.split("=", 1)[1])
    return DEFAULT_HMAX_REL


# ---------------------------------------------------------------- judging a mesh

def exposed_area(path):
    """Area of the tetrahedron faces used by exactly one tetrahedron (the mesh's outer boundary)."""
    import meshio
    import numpy as np
    m = meshio.read(path)
    points = np.asarray(m.points, float)
    tets = [np.asarray(c.data)[:, :4] for c in m.cells if c.type in ("tetra", "tetra10")]
    if not tets:
        return 0.0
    t = np.vstack(tets)
    faces = np.sort(np.vstack([t[:, [1, 2, 3]], t[:, [0, 2, 3]], t[:, [0, 1, 3]], t[:, [0, 1, 2]]]), axis=1)
    unique, count = np.unique(faces, axis=0, return_counts=True)
    f = unique[count == 1]
    a, b, c = points[f[:, 0]], points[f[:, 1]], points[f[:, 2]]
    return float(0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum())


def judge(meshq, entry, dim, mesh, r):
    """Adds the referee's figures and the errors to r, and r['why'] (the reasons to fail, empty
    when the mesh passes)."""
    why = r.setdefault("why", [])
    try:
        with contextlib.redirect_stdout(io.StringIO()):  # meshio prints a blank line per .msh read
            q = meshq.stats(mesh)
    except Exception as e:  # the referee's reader refused the file: report it, go on
        why.append(f"unreadable mesh: {str(e)[:80]}")
        return
    for k in ("tets", "tris", "inverted", "eta_avg", "dihedral_min", "tri_eta_avg", "edges_open"):
        if k in q:
            r[k] = q[k]
    if dim == 3:
        if not q.get("tets"):
            why.append("no tetrahedra")
            return
        reference = entry.get("union_volume") or entry.get("volume")
        if reference:  # no reference (the manifest's reader failed): validity only
            r["vol_err"] = round((q["volume"] - reference) / abs(reference), 5)
            if abs(r["vol_err"]) > VOLUME_TOL:
                why.append(f"volume off by {r['vol_err']:+.2%}")
        if q["inverted"]:
            why.append(f"{q['inverted']} inverted")
        if q["eta_avg"] < ETA_MIN_3D:
            why.append(f"eta_avg {q['eta_avg']}")
        if q["dihedral_min"] < DIHEDRAL_MIN:
            why.append(f"dihedral_min {q['dihedral_min']}")
        outer = entry.get("outer_area") or (entry.get("area") if entry.get("solids") == 1 else None)
        if outer:
            with contextlib.redirect_stdout(io.StringIO()):
                area = exposed_area(mesh)
            r["exposed_err"] = round((area - outer) / outer, 5)
            if abs(r["exposed_err"]) > EXPOSED_TOL:
                why.append(f"exposed area off by {r['exposed_err']:+.2%} (not conformal or wrong)")
    else:
        if not q.get("tris"):
            why.append("no triangles")
            return
        if entry.get("area"):
            r["area_err"] = round((q["tri_area"] - entry["area"]) / entry["area"], 5)
            if abs(r["area_err"]) > AREA_TOL:
                why.append(f"area off by {r['area_err']:+.2%}")
        if q["tri_eta_avg"] < ETA_MIN_2D:
            why.append(f"tri_eta_avg {q['tri_eta_avg']}")


def finish(r):
    """Sets r['pass'] from the run status and the reasons gathered."""
    if r["status"] not in ("ok/0", "degraded/0"):
        r["why"].insert(0, f"status {r['status']}")
    r["pass"] = not r["why"]


# ---------------------------------------------------------------- anisomesh

def first_message(stderr, report):
    """The first failure of the report, else the first warning/error line of stderr, else the
    first warning of the report (top level, its model summary or an 'extra' section)."""
    for failure in (report or {}).get("failures") or []:
        return f"{failure.get('entity', '?')}: {failure.get('what', '')}"
    for line in stderr.splitlines():
        if re.search(r"warning|error|fail|abort|terminate", line, re.IGNORECASE):
            return line.strip()
    report = report or {}
    for holder in (report, report.get("model") or {}, report.get("extra") or {}):
        warnings = holder.get("warnings") if isinstance(holder, dict) else None
        if warnings:
            return f"warning: {warnings[0]}"
    lines = stderr.strip().splitlines()
    return lines[-1].strip() if lines else ""


def run_anisomesh(args, meshq, entry, dim, workdir):
    path = os.path.join(args.dir, entry["file"])
    mesh, report_path = os.path.join(workdir, "out.msh"), os.path.join(workdir, "report.json")
    remove(mesh, report_path)
    cmd = [args.cli, "mesh", path, "-o", mesh, "--dim", str(dim), "--report", report_path] + shlex.split(args.extra)
    run = run_limited(cmd, args.time_limit, workdir)
    report = None
    if os.path.isfile(report_path):
        try:
            with open(report_path) as f:
                report = json.load(f)
        except ValueError:
            pass
    r = {"status": run_status(run, (report or {}).get("status")), "wall_s": run["wall_s"], "rss_mb": run["rss_mb"],
         "why": []}
    message = first_message(run["stderr"], report)
    if run["timeout"]:  # the limit first: a warning printed before the kill is not the reason
        message = f"killed after {args.time_limit:g} s" + (f"; last: {message}" if message else "")
    if message:
        r["message"] = message[:MESSAGE_CHARS]
    if run["code"] == 0 and not run["timeout"]:
        if report is None:
            r["why"].append("no report written")
        if os.path.isfile(mesh):
            judge(meshq, entry, dim, mesh, r)
        else:
            r["why"].append("no mesh written")
    finish(r)
    return r


# ---------------------------------------------------------------- Gmsh

def gmsh_driver(argv):
    """Child process: meshes one file with Gmsh (OpenCASCADE kernel, default algorithms, h_max =
    hrel x diagonal, 24 elements per 2 pi of curvature), writes --out, prints one JSON line."""
    ap = argparse.ArgumentParser()
    ap.add_argument("file")
    ap.add_argument("--dim", type=int, default=3)
    ap.add_argument("--hrel", type=float, required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--fragment", action="store_true")
    a = ap.parse_args(argv)
    import gmsh
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", CURVATURE_ELEMENTS)
    result = {"ok": False}
    try:
        gmsh.model.occ.importShapes(a.file)
        if a.fragment and len(gmsh.model.occ.getEntities(3)) > 1:
            gmsh.model.occ.fragment(gmsh.model.occ.getEntities(3), [])
        gmsh.model.occ.synchronize()
        x0, y0, z0, x1, y1, z1 = gmsh.model.getBoundingBox(-1, -1)
        gmsh.option.setNumber("Mesh.MeshSizeMax", a.hrel * ((x1 - x0) ** 2 + (y1 - y0) ** 2 + (z1 - z0) ** 2) ** 0.5)
        gmsh.model.mesh.generate(a.dim)
        gmsh.write(a.out)
        result["ok"] = True
    except Exception as e:
        result["error"] = str(e)[:MESSAGE_CHARS]
    print(json.dumps(result), flush=True)
    gmsh.finalize()


def run_gmsh(args, meshq, entry, dim, workdir):
    mesh = os.path.join(workdir, "gmsh.msh")
    remove(mesh)
    cmd = ["/usr/bin/python3", os.path.abspath(__file__), "--gmsh-driver", os.path.join(args.dir, entry["file"]),
           "--dim", str(dim), "--hrel", repr(hmax_rel(args.extra)), "--out", mesh]
    if args.gmsh_fragment:
        cmd.append("--fragment")
    limit = args.gmsh_time_limit or args.time_limit
    run = run_limited(cmd, limit, workdir)
    result = {}
    try:
        result = json.loads(run["stdout"].strip().splitlines()[-1])
    except (ValueError, IndexError):
        pass
    reported = "ok" if result.get("ok") else "failed"
    r = {"status": run_status(run, reported), "wall_s": run["wall_s"], "rss_mb": run["rss_mb"], "why": []}
    lines = run["stderr"].strip().splitlines()
    message = result.get("error") or (lines[-1] if run["code"] != 0 and lines else "")
    if run["timeout"]:
        message = f"killed after {limit:g} s"
    if message:
        r["message"] = message[:MESSAGE_CHARS]
    if result.get("ok") and os.path.isfile(mesh):
        judge(meshq, entry, dim, mesh, r)
    finish(r)
    return r


# ---------------------------------------------------------------- output

def figures(r, dim):
    """One mesher's figures, fixed width: status, time, RSS, count, quality, errors, verdict."""
    rss = f"{r['rss_mb']:>6.0f}MB" if r.get("rss_mb") is not None else f"{'-':>6}MB"
    s = f"{r['status']:<11} {r['wall_s']:>7.1f}s {rss}"
    if dim == 3 and "tets" in r:
        s += f" {r['tets']:>8} tets eta {r['eta_avg']:.3f} dih {r['dihedral_min']:>5.2f} inv {r['inverted']}"
        s += f" vol {r['vol_err']:+.2%}" if "vol_err" in r else " vol -"
        s += f" exp {r['exposed_err']:+.2%}" if "exposed_err" in r else " exp -"
    elif dim == 2 and "tris" in r:
        s += f" {r['tris']:>8} tris eta {r['tri_eta_avg']:.3f} area {r.get('area_err', 0):+.2%}"
    else:
        s += f" {'-':>8}"
    return s + (" PASS" if r["pass"] else " FAIL")


def print_line(entry, dim, us, gm, width):
    line = f"{entry['file']:<{width}} {dim}D  {figures(us, dim)}"
    if gm is not None:
        line += f"  | gmsh {figures(gm, dim)}"
    notes = []
    if us["why"]:
        notes.append("why: " + "; ".join(us["why"]))
    if us.get("message"):
        notes.append("first: " + us["message"])
    if gm is not None and gm["why"]:
        notes.append("gmsh why: " + "; ".join(gm["why"]) + (f" ({gm['message']})" if gm.get("message") else ""))
    if notes:
        line += "  | " + " | ".join(notes)
    print(line, flush=True)


def summary(name, rows, key, seconds):
    done = [r[key] for r in rows]
    passed = sum(r["pass"] for r in done)
    degraded = sum(r["pass"] and r["status"].startswith("degraded") for r in done)
    statuses = {}
    for r in done:
        word = r["status"].split("/")[0]
        statuses[word] = statuses.get(word, 0) + 1
    failed = [row["file"] for row in rows if not row[key]["pass"]]
    text = f"{name}: passed {passed}/{len(done)} ({degraded} degraded); " + ", ".join(
        f"{k} {v}" for k, v in sorted(statuses.items())) + f"; {seconds:.1f} s"
    if failed:
        text += "; failed: " + ", ".join(failed)
    print(text)
    return passed == len(done)


TABLE_COLUMNS = ("model", "dim", "status", "s", "MB", "elements", "mean ratio", "min dihedral", "vol/area err",
                 "exposed err", "pass")


def table(path):
    """Markdown rows of docs/census.md's results table from a --jsonl file (Gmsh's columns when
    the census ran with --gmsh)."""
    with open(path) as f:
        rows = [json.loads(x) for x in f if x.strip()]
    gmsh = any(r.get("gmsh") for r in rows)
    head = list(TABLE_COLUMNS) + ["Gmsh " + c for c in TABLE_COLUMNS[2:]] * gmsh
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for row in rows:
        cells = [row["file"], f"{row['dim']}D"] + table_cells(row["us"], row["dim"])
        if gmsh:
            cells += table_cells(row.get("gmsh") or {"status": "-"}, row["dim"])
        print("| " + " | ".join(cells) + " |")


def table_cells(r, dim):
    def number(key, form):
        return format(r[key], form) if r.get(key) is not None else "-"
    three = dim == 3
    return [r["status"], number("wall_s", ".1f"), number("rss_mb", ".0f"), number("tets" if three else "tris", "d"),
            number("eta_avg" if three else "tri_eta_avg", ".3f"), number("dihedral_min", ".2f") if three else "-",
            number("vol_err" if three else "area_err", "+.2%"), number("exposed_err", "+.2%"),
            {True: "yes", False: "no"}.get(r.get("pass"), "-")]


def main(argv):
    if argv[:1] == ["--gmsh-driver"]:
        gmsh_driver(argv[1:])
        return 0
    if argv[:1] == ["--table"] and len(argv) == 2:
        table(argv[1])
        return 0
    args = parse_args(argv)
    meshq = load_referee(args.shared)
    if meshq is None:
        print(f"census: no referee at {os.path.abspath(args.shared)}/tools/meshq.py (pass --shared DIR)", file=sys.stderr)
        return 2
    if not os.path.isdir(args.dir) or not os.access(args.cli, os.X_OK):
        print(f"census: no folder {args.dir} or no program {args.cli}", file=sys.stderr)
        return 2
    workdir = tempfile.mkdtemp(prefix="census-")
    t0 = time.perf_counter()
    try:
        entries = model_list(args, workdir)
        width = max([len(e["file"]) for e in entries] + [4])
        print(f"census of {os.path.abspath(args.dir)}: {len(entries)} models, anisomesh {args.extra or '(defaults)'}, "
              f"limit {args.time_limit:g} s" + (f"; gmsh --hmax-rel {hmax_rel(args.extra):g}, curvature "
                                                f"{CURVATURE_ELEMENTS} per 2 pi" if args.gmsh else ""), flush=True)
        rows = []
        for entry in entries:
            dim = dimension(entry)
            row = {"file": entry["file"], "dim": dim}
            if not os.path.isfile(os.path.join(args.dir, entry["file"])):
                row["us"] = {"status": "missing", "wall_s": 0, "rss_mb": 0, "why": ["file not found"], "pass": False}
            else:
                row["us"] = run_anisomesh(args, meshq, entry, dim, workdir)
            row["gmsh"] = run_gmsh(args, meshq, entry, dim, workdir) if args.gmsh and "missing" not in row["us"][
                "status"] else None
            rows.append(row)
            print_line(entry, dim, row["us"], row["gmsh"], width)
            if args.jsonl:
                with open(args.jsonl, "a") as f:
                    print(json.dumps(row), file=f)
        ours = summary("anisomesh", rows, "us", sum(r["us"]["wall_s"] for r in rows))
        if args.gmsh:
            summary("gmsh", [r for r in rows if r["gmsh"]], "gmsh", sum(r["gmsh"]["wall_s"] for r in rows if r["gmsh"]))
        print(f"total {time.perf_counter() - t0:.1f} s")
        return 0 if ours else 1
    finally:
        shutil.rmtree(workdir, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
