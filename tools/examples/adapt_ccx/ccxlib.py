#!/usr/bin/python3
"""Small CalculiX helpers shared by adapt_loop.sh and the adapt benchmarks (tools/bench/).

As a module: inp_nodes, inp_nset, face_with_nodes_at, static_steel_deck, mesh_c3d10,
frd_mises, run_ccx. As a program:
  ccxlib.py nset-count MESH.inp NAME   the number of nodes of *NSET NAME
  ccxlib.py max-mises JOB.frd          the largest nodal von Mises stress of the last STRESS block
  ccxlib.py nodes MESH.inp             the number of nodes of the *NODE blocks
"""
import math
import os
import subprocess
import sys


def inp_nodes(path):
    """{node id: (x, y, z)} of the *NODE blocks of an Abaqus / CalculiX deck."""
    nodes, on = {}, False
    for line in open(path):
        if line.startswith("*"):
            on = line.split(",")[0].strip().upper() == "*NODE"
            continue
        if on and line.strip():
            v = line.split(",")
            nodes[int(v[0])] = tuple(float(x) for x in v[1:4])
    return nodes


def inp_nset(path, name):
    """Node ids of *NSET, NSET=name (case-insensitive; GENERATE is not used by anisomesh)."""
    ids, on = [], False
    for line in open(path):
        if line.startswith("*"):
            on = line.replace(" ", "").strip().upper() == "*NSET,NSET=" + name.upper()
            continue
        if on:
            ids += [int(x) for x in line.replace(" ", "").strip().split(",") if x]
    return ids


def face_with_nodes_at(inp, axis, value, tol, nodes=None):
    """n of the node set FACE<n> whose nodes all lie within tol of coordinate `axis` = value;
    None when no face set does. `nodes`: inp_nodes(inp) when already read."""
    nodes = nodes if nodes is not None else inp_nodes(inp)
    n = 1
    while ids := inp_nset(inp, f"FACE{n}"):
        if max(abs(nodes[i][axis] - value) for i in ids) < tol:
            return n
        n += 1
    return None


def static_steel_deck(workdir, step):
    """Writes WORKDIR/job.inp: mesh.inp included, steel (E 210000 MPa, nu 0.3) on EALL, one
    static step holding `step` (boundary conditions, loads, output requests)."""
    with open(os.path.join(workdir, "job.inp"), "w") as fp:
        fp.write("*INCLUDE, INPUT=mesh.inp\n*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n"
                 "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n*STEP\n*STATIC\n" + step.strip() + "\n*END STEP\n")


def mesh_c3d10(cli, args, workdir):
    """anisomesh ARGS -o WORKDIR/mesh.inp --order 2 -q (ARGS: `mesh MODEL ...` or `adapt MODEL
    --from ...`); raises CalledProcessError when it fails."""
    os.makedirs(workdir, exist_ok=True)
    subprocess.run([cli, *args, "-o", os.path.join(workdir, "mesh.inp"), "--order", "2", "-q"], check=True)


def von_mises(s):
    """von Mises stress of (sxx, syy, szz, sxy, syz, szx)."""
    a, b, c = s[0] - s[1], s[1] - s[2], s[2] - s[0]
    return math.sqrt(0.5 * (a * a + b * b + c * c) + 3 * (s[3] ** 2 + s[4] ** 2 + s[5] ** 2))


def frd_mises(path):
    """{node id: von Mises} of the last STRESS block of a CalculiX .frd (ASCII, fixed columns:
    ' -1', the node id in 10 columns, then 12 columns per value)."""
    lines = open(path).read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith(" -4  STRESS"))
    vm = {}
    for l in lines[start + 1:]:
        if l.startswith(" -3"):
            break
        if l.startswith(" -1"):
            vm[int(l[3:13])] = von_mises([float(l[13 + 12 * c: 25 + 12 * c]) for c in range(6)])
    return vm


def run_ccx(workdir, job="job"):
    """Runs ccx on WORKDIR/JOB.inp; raises RuntimeError naming the folder if it fails."""
    with open(os.path.join(workdir, "ccx.log"), "w") as log:
        rc = subprocess.run(["ccx", job], cwd=workdir, stdout=log, stderr=subprocess.STDOUT).returncode
    text = open(os.path.join(workdir, "ccx.log")).read()
    if rc != 0 or "*ERROR" in text:
        err = next((l for l in text.splitlines() if "*ERROR" in l), f"exit {rc}")
        raise RuntimeError(f"ccx failed in {workdir}: {err.strip()}")


if __name__ == "__main__":
    cmd = sys.argv[1] if len(sys.argv) > 1 else ""
    if cmd == "nset-count" and len(sys.argv) == 4:
        print(len(inp_nset(sys.argv[2], sys.argv[3])))
    elif cmd == "max-mises" and len(sys.argv) == 3:
        print(f"{max(frd_mises(sys.argv[2]).values()):.4f}")
    elif cmd == "nodes" and len(sys.argv) == 3:
        print(len(inp_nodes(sys.argv[2])))
    else:
        sys.exit(__doc__)
