# anisomesh inside FreeCAD: mesh Part objects with the anisomesh CLI and bring the result
# back as a Fem::FemMeshObject linked to its shape (issues 8, 17). Used by AnisoMesh.FCMacro,
# in the GUI (anisomesh_dialog.py) or headless (environment variables, for scripts and tests).
# Only FreeCAD's own modules are imported.
#
# Flow: the shapes of the objects, with their global placement (Part.getShape), are written
# to one BREP file in a temporary folder; `anisomesh --progress mesh in.brep -o out.unv
# --report report.json OPTIONS` meshes them (one conformal mesh: touching solids share their
# interfaces); Fem.read reads the UNV with its groups; the groups are renamed after the
# objects and their faces (anisomesh_groups.py: Box, Box_Face3, ...); a new FemMeshObject
# gets the mesh, a `Part` link to the meshed object (as FreeCAD's Gmsh mesh object has, so
# the CalculiX tools know the geometry) and goes into the FEM analysis (the active one in the
# GUI, the only one headless). On any failure nothing is created: the CLI's one-line message
# is shown (GUI) or printed and the macro exits non-zero (headless).
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

import FreeCAD

from anisomesh_groups import name_groups
from anisomesh_options import build_command, failure_message, summary_line, warnings_of

# Relative to the shapes' bounding-box diagonal: the distance under which a mesh face is taken
# to lie on an object's face (anisomesh_groups.py adds a margin scaled by the mesh).
FACE_MATCH_TOLERANCE = 1e-6
# The object that stands for several selected objects in the mesh's Part link.
COMPOUND_NAME = "AnisoMeshParts"


class MeshingFailed(Exception):
    """The CLI failed or its result could not be read: the message says why."""


class Result:
    """A finished run: the new FemMeshObject, the CLI's report, the warnings and a summary line."""

    def __init__(self, obj, report, warnings, summary):
        self.obj, self.report, self.warnings, self.summary = obj, report, warnings, summary


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
    cand = os.path.normpath(os.path.join(here, "..", "..", "build", "anisomesh"))
    if os.path.isfile(cand) and os.access(cand, os.X_OK):
        return cand
    raise MeshingFailed("anisomesh not found: set ANISOMESH or put it on PATH")


def shapes_of(objects):
    """The objects' shapes with their global placement (Part.getShape), in order."""
    import Part

    if not objects:
        raise MeshingFailed("nothing to mesh: no object selected")
    shapes = []
    for obj in objects:
        shape = Part.getShape(obj)
        if shape.isNull():
            raise MeshingFailed(f"{obj.Name}: the object has no shape")
        shapes.append(shape)
    return shapes


def diagonal_of(shapes):
    """The bounding-box diagonal of all shapes together (model units)."""
    box = FreeCAD.BoundBox()
    for s in shapes:
        box.add(s.BoundBox)
    return box.DiagonalLength


def export_shapes(shapes, folder):
    """Writes the shapes (one compound when several) to folder/input.brep; returns the path."""
    import Part

    shape = shapes[0] if len(shapes) == 1 else Part.makeCompound(shapes)
    path = os.path.join(folder, "input.brep")
    shape.exportBrep(path)
    return path


def solid_names(objects, shapes):
    """The name of each solid of the exported compound, in order: Obj, or Obj_Solid<k> when
    the object has several solids."""
    out = []
    for obj, shape in zip(objects, shapes):
        n = len(shape.Solids)
        out += [obj.Name] if n == 1 else [f"{obj.Name}_Solid{k}" for k in range(1, n + 1)]
    return out


def translate_solids(text, names):
    """Replaces the CLI's solid names (SOLID<k>) in a message by the objects' names."""
    return re.sub(r"\bSOLID(\d+)\b",
                  lambda m: names[int(m.group(1)) - 1] if 0 < int(m.group(1)) <= len(names) else m.group(0), text)


def read_mesh(unv, objects, shapes):
    """Reads the UNV and names its groups after the objects. Returns (mesh, warnings)."""
    import Fem

    if not os.path.isfile(unv):
        raise MeshingFailed(f"{unv}: anisomesh wrote no mesh")
    mesh = Fem.read(unv)
    if mesh.NodeCount == 0:
        raise MeshingFailed(f"{unv}: the mesh is empty")
    warnings = name_groups(mesh, [o.Name for o in objects], [s.Faces for s in shapes],
                           [len(s.Solids) for s in shapes], FACE_MATCH_TOLERANCE * diagonal_of(shapes))
    return mesh, warnings


def shape_link(doc, objects):
    """The object the mesh is made from: the selected object, or for several a Part::Compound
    of them (an existing one with exactly these links is reused)."""
    if len(objects) == 1:
        return objects[0]
    for o in doc.Objects:
        if o.TypeId == "Part::Compound" and list(o.Links) == list(objects):
            return o
    comp = doc.addObject("Part::Compound", COMPOUND_NAME)
    comp.Links = list(objects)
    return comp


def find_analysis(doc, active=None):
    """The active analysis if given, else the document's only FEM analysis, else None."""
    if active is not None:
        return active
    analyses = [o for o in doc.Objects if o.TypeId == "Fem::FemAnalysis"]
    return analyses[0] if len(analyses) == 1 else None


def add_mesh_object(doc, mesh, objects, options, analysis=None):
    """A new FemMeshObject holding `mesh`, its `Part` link set to the meshed shape and the CLI
    options recorded in `AnisoMeshOptions`; put into `analysis` when there is one."""
    base = "AnisoMesh"
    obj = doc.addObject("Fem::FemMeshObject", base)
    obj.FemMesh = mesh
    # FreeCAD's FEM tools look for `Part` (Gmsh mesh objects) or `Shape` (Netgen) to know the
    # geometry; without either, the CalculiX writer warns "Not all methods do work".
    obj.addProperty("App::PropertyLink", "Part", "FEM Mesh", "Geometry object the mesh is made from")
    obj.Part = shape_link(doc, objects)
    obj.addProperty("App::PropertyString", "AnisoMeshOptions", "FEM Mesh", "anisomesh options of this mesh")
    obj.AnisoMeshOptions = shlex.join(options)
    label = "+".join(o.Label for o in objects)
    obj.Label = f"{base} of {label}" if label else base
    if analysis is not None:
        analysis.addObject(obj)
    doc.recompute()
    return obj


def prefix_clashes(mesh, analysis):
    """Warnings for groups whose name starts with "<member>_" for a member of the analysis:
    FreeCAD's FEM tools (meshtools.get_femmesh_groupdata_sets_by_name) take such a group as the
    member's node or element set instead of its references."""
    if analysis is None:
        return []
    out = []
    members = [o for o in analysis.Group if not o.isDerivedFrom("Fem::FemMeshObject")]
    for gid in mesh.Groups:
        name = mesh.getGroupName(gid)
        for o in members:
            if name.startswith(o.Name + "_"):
                out.append(f"group {name} starts with the name of {o.Name}: FreeCAD's solver writers would take it "
                           f"for {o.Name}'s set instead of its references; rename {o.Name} or the object")
    return out


def finish_run(doc, objects, shapes, folder, stderr, options, analysis=None):
    """After a successful CLI run in `folder`: reads the mesh, makes the FemMeshObject.
    Returns a Result."""
    with open(os.path.join(folder, "report.json")) as f:
        report = json.load(f)
    mesh, group_warnings = read_mesh(os.path.join(folder, "mesh.unv"), objects, shapes)
    names = solid_names(objects, shapes)
    brep = os.path.join(folder, "input.brep") + ": "
    warnings = [translate_solids(w.replace(brep, ""), names) for w in warnings_of(stderr)] + group_warnings
    warnings += prefix_clashes(mesh, analysis)
    obj = add_mesh_object(doc, mesh, objects, options, analysis)
    summary = summary_line(obj.Label, report, mesh.NodeCount, len(mesh.Groups), len(warnings))
    return Result(obj, report, warnings, summary)


def run_blocking(doc, objects, options, analysis=None):
    """Exports, runs the CLI to completion, reads the mesh, makes the FemMeshObject.
    Returns a Result; raises MeshingFailed (nothing created) when the CLI fails."""
    cli = find_cli()
    shapes = shapes_of(objects)
    folder = tempfile.mkdtemp(prefix="anisomesh-")
    try:
        brep = export_shapes(shapes, folder)
        report = os.path.join(folder, "report.json")
        cmd = build_command(cli, brep, os.path.join(folder, "mesh.unv"), report, options)
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if proc.returncode != 0:
            raise MeshingFailed(failure_message(proc.returncode, proc.stderr, report))
        return finish_run(doc, objects, shapes, folder, proc.stderr, options, analysis)
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def objects_by_name(doc, names):
    """The document's objects of these names; MeshingFailed naming the first missing one."""
    objects = []
    for n in names:
        o = doc.getObject(n)
        if o is None:
            raise MeshingFailed(f"{doc.FileName or doc.Name}: no object named {n}")
        objects.append(o)
    return objects


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
        if not names:
            raise MeshingFailed("no objects: set ANISOMESH_OBJECTS (comma-separated object names)")
        result = run_blocking(doc, objects_by_name(doc, names), options, find_analysis(doc))
        for w in result.warnings:
            sys.stderr.write(f"anisomesh: warning: {w}\n")
        sys.stderr.write(f"anisomesh: {result.summary}\n")
        if save:
            doc.saveAs(save)
        return 0
    except MeshingFailed as e:
        sys.stderr.write(f"anisomesh: {e}\n")
        return 3
    except Exception as e:  # noqa: BLE001 - freecadcmd would exit 0 on an uncaught exception
        sys.stderr.write(f"anisomesh: {type(e).__name__}: {e}\n")
        return 1


def main():
    """Headless when FreeCAD has no GUI or ANISOMESH_OBJECTS is set; else the dialog."""
    if not FreeCAD.GuiUp or os.environ.get("ANISOMESH_OBJECTS"):
        return run_headless()
    import anisomesh_dialog

    anisomesh_dialog.open_for_selection()
    return 0
