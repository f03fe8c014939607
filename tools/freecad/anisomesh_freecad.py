# anisomesh inside FreeCAD: mesh Part objects with the anisomesh CLI and bring the result
# back as a Fem::FemMeshObject (issue 8). Used by AnisoMesh.FCMacro, in the GUI (a dialog,
# the CLI run by QProcess so the interface stays responsive) or headless (environment
# variables, for scripts and tests). Only FreeCAD's own modules are imported.
#
# Flow: the shapes of the objects, with their global placement (Part.getShape), are
# written to one BREP file in a temporary folder; `anisomesh --progress mesh in.brep -o
# out.unv --report report.json OPTIONS` meshes them (one conformal mesh: touching solids
# share their interfaces); Fem.read reads the UNV with its groups; the groups are renamed
# after FreeCAD's sub-element names (FACE<n> -> Face<n>, the i-th solid group -> Solid<i>)
# so they match the shape the user sees; a new FemMeshObject gets the mesh and goes into
# the FEM analysis (the active one in the GUI, the only one headless). On any failure
# nothing is created: the CLI's one-line message is shown (GUI) or printed and the macro
# exits non-zero (headless).
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

import FreeCAD

# FreeCAD's UNV import splits a group holding nodes and elements into NAME_Nodes and
# NAME_Faces (NAME_Volumes, ...): the face groups come back as FACE<n>_Nodes, FACE<n>_Faces.
FACE_GROUP = re.compile(r"^FACE(\d+)(?:_(Nodes|Edges|Faces|Volumes))?$")


class MeshingFailed(Exception):
    """The CLI failed or its result could not be read: the message says why."""


def find_cli():
    """The anisomesh executable: $ANISOMESH, else PATH, else a build next to this file."""
    env = os.environ.get("ANISOMESH")
    if env:
        if os.path.isfile(env) and os.access(env, os.X_OK):
            return env
        raise MeshingFailed(f"ANISOMESH={env}: not an executable file")
    found = shutil.which("anisomesh")
    if found:
        return found
    here = os.path.dirname(os.path.abspath(__file__))
    for cand in (os.path.join(here, "..", "..", "build", "anisomesh"),):
        if os.path.isfile(cand) and os.access(cand, os.X_OK):
            return os.path.normpath(cand)
    raise MeshingFailed("anisomesh not found: set ANISOMESH or put it on PATH")


def export_shapes(objects, folder):
    """Writes the objects' shapes (global placement) to folder/input.brep; returns the path."""
    import Part

    shapes = []
    for obj in objects:
        shape = Part.getShape(obj)
        if shape.isNull():
            raise MeshingFailed(f"{obj.Name}: the object has no shape")
        shapes.append(shape)
    if not shapes:
        raise MeshingFailed("nothing to mesh: no object selected")
    shape = shapes[0] if len(shapes) == 1 else Part.makeCompound(shapes)
    path = os.path.join(folder, "input.brep")
    shape.exportBrep(path)
    return path


def build_command(cli, brep, unv, report, options):
    """The CLI command line; `options` is a list of extra arguments."""
    return [cli, "--progress", "mesh", brep, "-o", unv, "--report", report] + list(options)


def options_from_settings(s):
    """CLI arguments from the dialog's settings (a dict; missing or None = CLI default)."""
    args = []
    if s.get("hmax"):
        args += ["--hmax", repr(float(s["hmax"]))]
    if s.get("size"):
        args += ["--size", repr(float(s["size"]))]
    if s.get("order") == 2:
        args += ["--order", "2"]
    if s.get("quad"):
        args += ["--quad", "--dim", "2"]
    elif s.get("dim"):
        args += ["--dim", str(int(s["dim"]))]
    for key, flag in (("anisotropy", "--anisotropy"), ("curvature_ratio", "--curvature-ratio"),
                      ("elements_per_circle", "--elements-per-circle"), ("gradation", "--gradation")):
        if s.get(key):
            args += [flag, repr(float(s[key]))]
    return args


def failure_message(returncode, stderr, report):
    """The CLI's own one-line message, else the report's first failure, else the exit code."""
    lines = [l for l in stderr.splitlines() if l.strip() and not l.startswith("progress:")]
    if lines:
        last = lines[-1].strip()
        return last[len("anisomesh: "):] if last.startswith("anisomesh: ") else last
    try:
        with open(report) as f:
            r = json.load(f)
        if r.get("failures"):
            first = r["failures"][0]
            return f"{first.get('entity', '')}: {first.get('what', '')}"
    except (OSError, ValueError):
        pass
    return f"anisomesh failed with exit code {returncode}"


def read_mesh(unv):
    """Reads the UNV and renames its groups after FreeCAD's Face<n> / Solid<n>."""
    import Fem

    if not os.path.isfile(unv):
        raise MeshingFailed(f"{unv}: anisomesh wrote no mesh")
    mesh = Fem.read(unv)
    if mesh.NodeCount == 0:
        raise MeshingFailed(f"{unv}: the mesh is empty")
    rename_groups(mesh)
    return mesh


def rename_groups(mesh):
    """FACE<n>'s node group -> Face<n>, its element group -> Face<n>_Faces; the volume
    groups, in file order, -> Solid1, Solid2, ...

    FemMesh has no rename: each group is copied under its new name and the old one removed.
    """
    solid = 0
    for gid in list(mesh.Groups):
        name = mesh.getGroupName(gid)
        kind = mesh.getGroupElementType(gid)
        m = FACE_GROUP.match(name)
        if m:
            new = f"Face{m.group(1)}" if kind == "Node" else f"Face{m.group(1)}_{kind}s"
        elif kind == "Volume":
            solid += 1
            new = f"Solid{solid}"
        else:
            continue
        if new == name:
            continue
        elements = list(mesh.getGroupElements(gid))
        ng = mesh.addGroup(new, kind)
        if elements:
            mesh.addGroupElements(ng, elements)
        mesh.removeGroup(gid)


def find_analysis(doc, active=None):
    """The active analysis if given, else the document's only FEM analysis, else None."""
    if active is not None:
        return active
    analyses = [o for o in doc.Objects if o.TypeId == "Fem::FemAnalysis"]
    return analyses[0] if len(analyses) == 1 else None


def add_mesh_object(doc, mesh, objects, analysis=None):
    """A new FemMeshObject holding `mesh`, put into `analysis` when there is one."""
    base = "AnisoMesh"
    obj = doc.addObject("Fem::FemMeshObject", base)
    obj.FemMesh = mesh
    label = "+".join(o.Label for o in objects)
    obj.Label = f"{base} of {label}" if label else base
    if analysis is not None:
        analysis.addObject(obj)
    doc.recompute()
    return obj


def run_blocking(objects, options, workdir=None):
    """Exports, runs the CLI to completion, reads the mesh. Returns (mesh, report dict)."""
    cli = find_cli()
    folder = workdir or tempfile.mkdtemp(prefix="anisomesh-")
    try:
        brep = export_shapes(objects, folder)
        unv = os.path.join(folder, "mesh.unv")
        report = os.path.join(folder, "report.json")
        proc = subprocess.run(build_command(cli, brep, unv, report, options), capture_output=True, text=True)
        if proc.returncode != 0:
            raise MeshingFailed(failure_message(proc.returncode, proc.stderr, report))
        mesh = read_mesh(unv)
        with open(report) as f:
            rep = json.load(f)
        return mesh, rep
    finally:
        if workdir is None:
            shutil.rmtree(folder, ignore_errors=True)


def run_headless():
    """Environment-driven run (see README): returns the process exit code."""
    doc_path = os.environ.get("ANISOMESH_DOCUMENT")
    names = [n.strip() for n in os.environ.get("ANISOMESH_OBJECTS", "").split(",") if n.strip()]
    options = shlex.split(os.environ.get("ANISOMESH_OPTIONS", ""))
    save = os.environ.get("ANISOMESH_SAVE")
    try:
        if doc_path:
            if not os.path.isfile(doc_path):
                raise MeshingFailed(f"{doc_path}: no such document")
            doc = FreeCAD.openDocument(doc_path)
        else:
            doc = FreeCAD.ActiveDocument
        if doc is None:
            raise MeshingFailed("no document: set ANISOMESH_DOCUMENT")
        if names:
            objects = []
            for n in names:
                o = doc.getObject(n)
                if o is None:
                    raise MeshingFailed(f"{doc.FileName or doc.Name}: no object named {n}")
                objects.append(o)
        else:
            raise MeshingFailed("no objects: set ANISOMESH_OBJECTS (comma-separated object names)")
        mesh, rep = run_blocking(objects, options)
        obj = add_mesh_object(doc, mesh, objects, find_analysis(doc))
        counts = rep.get("counts", {})
        sys.stderr.write(f"anisomesh: {obj.Name}: {mesh.NodeCount} nodes, {counts.get('tetrahedra', 0)} tetrahedra, "
                         f"{counts.get('triangles', 0)} triangles, {len(mesh.Groups)} groups\n")
        if save:
            doc.saveAs(save)
        return 0
    except MeshingFailed as e:
        sys.stderr.write(f"anisomesh: {e}\n")
        return 3
    except Exception as e:  # noqa: BLE001 - freecadcmd would exit 0 on an uncaught exception
        sys.stderr.write(f"anisomesh: {type(e).__name__}: {e}\n")
        return 1


def run_gui():
    """The dialog: options, a progress bar fed by the CLI's progress lines, the result."""
    import FreeCADGui
    from PySide import QtCore, QtGui

    doc = FreeCAD.ActiveDocument
    objects = [o for o in FreeCADGui.Selection.getSelection() if hasattr(o, "Shape")]
    if doc is None or not objects:
        QtGui.QMessageBox.warning(None, "AnisoMesh", "Select one or more Part objects to mesh.")
        return
    try:
        cli = find_cli()
    except MeshingFailed as e:
        QtGui.QMessageBox.critical(None, "AnisoMesh", str(e))
        return
    try:
        import FemGui
        active = FemGui.getActiveAnalysis()
    except Exception:  # noqa: BLE001 - no FEM GUI: no active analysis
        active = None

    dialog = QtGui.QDialog(FreeCADGui.getMainWindow())
    dialog.setWindowTitle("AnisoMesh: " + ", ".join(o.Label for o in objects))
    form = QtGui.QFormLayout(dialog)

    def spin(value, lo, hi, step, decimals=3, special=None):
        w = QtGui.QDoubleSpinBox()
        w.setRange(lo, hi)
        w.setDecimals(decimals)
        w.setSingleStep(step)
        w.setValue(value)
        if special:
            w.setSpecialValueText(special)
        return w

    diag = max(o.Shape.BoundBox.DiagonalLength for o in objects)
    hmax = spin(0.0, 0.0, 1e9, max(diag / 100, 1e-3), special="automatic")
    order = QtGui.QComboBox()
    order.addItems(["1 (linear)", "2 (quadratic)"])
    quad = QtGui.QCheckBox("quad-dominant surface mesh")
    # the CLI's defaults (README, "Element size"): isotropic tets, 12 elements per circle
    aniso = spin(1.0, 1.0, 100.0, 0.5, 2)
    curv = spin(12, 4, 200, 1, 0)
    grad = spin(4.0, 1.1, 100.0, 0.5, 2)
    form.addRow("Largest size (hmax)", hmax)
    form.addRow("Element order", order)
    form.addRow("", quad)
    form.addRow("Largest stretch (1 = isotropic)", aniso)
    form.addRow("Elements per circle", curv)
    form.addRow("Gradation", grad)
    bar = QtGui.QProgressBar()
    bar.setRange(0, 100)
    status = QtGui.QLabel("")
    form.addRow(bar)
    form.addRow(status)
    buttons = QtGui.QDialogButtonBox(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)
    form.addRow(buttons)

    state = {"proc": None, "folder": None, "stderr": ""}

    def finish(ok_message=None, error=None):
        if state["folder"]:
            shutil.rmtree(state["folder"], ignore_errors=True)
            state["folder"] = None
        state["proc"] = None
        buttons.button(QtGui.QDialogButtonBox.Ok).setEnabled(True)
        if error:
            QtGui.QMessageBox.critical(dialog, "AnisoMesh", error)
        else:
            dialog.accept()

    def on_stderr():
        proc = state["proc"]
        text = bytes(proc.readAllStandardError()).decode("utf-8", "replace")
        state["stderr"] += text
        for line in text.splitlines():
            m = re.match(r"^progress: (\S+) (\d+)% ?(.*)$", line)
            if m:
                bar.setValue(int(m.group(2)))
                status.setText(f"{m.group(1)} {m.group(3)}")

    def on_finished(code, _status):
        folder = state["folder"]
        if code != 0:
            finish(error=failure_message(code, state["stderr"], os.path.join(folder, "report.json")))
            return
        try:
            mesh = read_mesh(os.path.join(folder, "mesh.unv"))
            add_mesh_object(doc, mesh, objects, find_analysis(doc, active))
        except Exception as e:  # noqa: BLE001 - shown to the user, nothing created
            finish(error=str(e))
            return
        finish()

    def start():
        settings = {"hmax": hmax.value() or None, "order": order.currentIndex() + 1, "quad": quad.isChecked(),
                    "anisotropy": aniso.value(), "elements_per_circle": curv.value(), "gradation": grad.value()}
        try:
            folder = tempfile.mkdtemp(prefix="anisomesh-")
            state["folder"] = folder
            brep = export_shapes(objects, folder)
        except Exception as e:  # noqa: BLE001
            finish(error=str(e))
            return
        cmd = build_command(cli, brep, os.path.join(folder, "mesh.unv"), os.path.join(folder, "report.json"),
                            options_from_settings(settings))
        proc = QtCore.QProcess(dialog)
        state["proc"], state["stderr"] = proc, ""
        proc.readyReadStandardError.connect(on_stderr)
        proc.finished.connect(on_finished)
        buttons.button(QtGui.QDialogButtonBox.Ok).setEnabled(False)
        status.setText("meshing...")
        proc.start(cmd[0], cmd[1:])

    def cancel():
        if state["proc"] is not None:
            state["proc"].kill()
            state["proc"].waitForFinished(3000)
        if state["folder"]:
            shutil.rmtree(state["folder"], ignore_errors=True)
        dialog.reject()

    buttons.accepted.connect(start)
    buttons.rejected.connect(cancel)
    dialog.show()


def main():
    """Headless when FreeCAD has no GUI or ANISOMESH_OBJECTS is set; else the dialog."""
    if not FreeCAD.GuiUp or os.environ.get("ANISOMESH_OBJECTS"):
        return run_headless()
    run_gui()
    return 0
