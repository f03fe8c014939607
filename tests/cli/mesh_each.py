"""One `anisomesh mesh` run per public model and option set, shared by the CLI regression
scripts (surface_mesh_test.py, volume_mesh_test.py): each run writes OUT and its report in
a temporary folder; a run that times out, exits non-zero or leaves an output file behind
after failing is appended to `failed`, the others are yielded for the script's checks."""
import os
import subprocess


def mesh_each(cli, models, manifest, runs, dim, timeout, folder, failed):
    """Yields (model entry, run name, mesh path, report path) for every successful run."""
    for extra in runs:
        for m in manifest:
            out, rep = os.path.join(folder, "out.msh"), os.path.join(folder, "rep.json")
            for x in (out, rep):
                if os.path.exists(x):
                    os.remove(x)
            name = f"{m['file']} {' '.join(extra) or 'defaults'}"
            cmd = [cli, "mesh", os.path.join(models, m["file"]), "-o", out, "--dim", str(dim), "--report", rep] + extra
            try:
                p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
            except subprocess.TimeoutExpired:
                failed.append(f"{name}: timeout")
                continue
            if p.returncode != 0:
                if os.path.exists(out):
                    failed.append(f"{name}: output file left behind by a failure")
                failed.append(f"{name}: exit {p.returncode}: {p.stderr.strip()[-200:]}")
                continue
            yield m, name, out, rep
