# The anisomesh CLI as the FreeCAD macro talks to it: its defaults (read from `anisomesh mesh
# --help`, never copied here), the command line built from the dialog's settings, and what
# its stderr and report say back (failure message, warnings, one-line summary).
# Pure Python: no FreeCAD import, so it can be tested anywhere.
import json
import re
import subprocess

# The dialog's settings, each with its CLI option and the --help option holding its default
# (None: no default value in --help, e.g. --size, whose default is "not set").
SETTINGS = (
    # key,                 CLI option,              option whose default is shown
    ("size",                "--size",                None),
    ("hmax",                "--hmax",                "--hmax-rel"),
    ("hmin",                "--hmin",                "--hmin-rel"),
    ("elements_per_circle", "--elements-per-circle", "--elements-per-circle"),
    ("order",               "--order",               "--order"),
)

_DEFAULT = re.compile(r"^\s*(?:-\w,)?(--[\w-]+)\b.*\(default ([^)\s]+)\)\s*$")


def cli_defaults(cli):
    """{option: default text} for every option of `CLI mesh --help` that states
    "(default X)", e.g. {"--order": "1", "--hmax-rel": "0.1", ...}. Raises OSError or
    subprocess.CalledProcessError when the CLI cannot be run."""
    proc = subprocess.run([cli, "mesh", "--help"], capture_output=True, text=True, check=True, timeout=60)
    out = {}
    for line in proc.stdout.splitlines():
        m = _DEFAULT.match(line)
        if m:
            out[m.group(1)] = m.group(2)
    return out


def dialog_defaults(defaults, diagonal):
    """The values the dialog shows, {key: number or None}, from cli_defaults() and the
    bounding-box diagonal of the selected shapes: max/min size are the CLI's relative
    defaults times the diagonal (what the CLI computes for the same shapes); None where the
    CLI has no default value (element size: not set) or --help does not state one."""
    def num(option):
        try:
            return float(defaults[option])
        except (KeyError, ValueError):
            return None

    rel_max, rel_min = num("--hmax-rel"), num("--hmin-rel")
    order = num("--order")
    return {
        "size": None,
        "hmax": rel_max * diagonal if rel_max is not None else None,
        "hmin": rel_min * diagonal if rel_min is not None else None,
        "elements_per_circle": num("--elements-per-circle"),
        "order": int(order) if order is not None else None,
    }


def options_from_settings(settings, shown):
    """CLI arguments for the dialog's `settings` ({key: value}): a value is sent only when it
    differs from the default the dialog showed (`shown`, from dialog_defaults), so an
    untouched dialog runs the CLI with its own defaults. `quad` adds --quad (a quad-dominant
    surface mesh), `surface` adds --dim 2, `extra` (a list) is appended as given."""
    args = []
    for key, flag, _ in SETTINGS:
        value = settings.get(key)
        if value is None or value == 0:
            continue
        default = shown.get(key)
        if default is not None and abs(value - default) <= 1e-9 * max(abs(default), 1.0):
            continue
        args += [flag, str(int(value)) if key == "order" else repr(float(value))]
    if settings.get("quad"):
        args.append("--quad")
    if settings.get("surface") or settings.get("quad"):
        args += ["--dim", "2"]
    return args + list(settings.get("extra", []))


def build_command(cli, brep, unv, report, options):
    """The CLI command line; `options` is a list of extra arguments."""
    return [cli, "--progress", "mesh", brep, "-o", unv, "--report", report] + list(options)


def message_lines(stderr):
    """The CLI's stderr without its progress lines and without the "anisomesh: " prefix."""
    out = []
    for line in stderr.splitlines():
        if not line.strip() or line.startswith("progress:"):
            continue
        out.append(line[len("anisomesh: "):] if line.startswith("anisomesh: ") else line)
    return out


def warnings_of(stderr):
    """The CLI's warning lines ("anisomesh: warning: ..."), without prefix, each once, in order."""
    seen = []
    for line in message_lines(stderr):
        if line.startswith("warning: ") and line[len("warning: "):] not in seen:
            seen.append(line[len("warning: "):])
    return seen


def failure_message(returncode, stderr, report):
    """The CLI's own one-line message, else the report's first failure, else the exit code."""
    lines = message_lines(stderr)
    if lines:
        return lines[-1].strip()
    try:
        with open(report) as f:
            r = json.load(f)
        if r.get("failures"):
            first = r["failures"][0]
            return f"{first.get('entity', '')}: {first.get('what', '')}"
    except (OSError, ValueError):
        pass
    return f"anisomesh failed with exit code {returncode}"


def summary_line(name, report, node_count, group_count, warning_count):
    """One line: object, nodes, elements by type, quality (the report's measure of the main
    elements: mean ratio, or scaled jacobian for quads; min/mean), groups, time, warnings."""
    counts = report.get("counts", {})
    parts = [f"{node_count} nodes"]
    for key in ("tetrahedra", "triangles", "quads"):
        if counts.get(key):
            parts.append(f"{counts[key]} {key}")
    q = report.get("quality", {}).get("elements", {})
    if q.get("count") == 0 and "quads" in q:  # a quad-only surface mesh: the quads' measure
        q = q["quads"]
    if q.get("count") and "min" in q and "mean" in q:
        measure = q.get("measure", "quality").replace("_", " ")
        parts.append(f"{measure} min {q['min']:.2f} mean {q['mean']:.2f}")
    parts.append(f"{group_count} groups")
    t = report.get("times", {}).get("total")
    if t is not None:
        parts.append(f"{t:.1f} s")
    parts.append(f"{warning_count} warning{'s' if warning_count != 1 else ''}")
    return f"{name}: " + ", ".join(parts)
