# Run by freecad_macro_test.sh through freecadcmd: FreeCAD's own CalculiX workflow on a mesh
# made by the macro's library (issue 17). A 40x10x10 box in a FEM analysis, meshed by
# anisomesh_freecad.run_blocking (--hmax 4); steel; ConstraintFixed on Box Face1 (x = 0),
# ConstraintForce 1000 N along +x on Box Face2 (x = 40); FreeCAD's ccxtools checks, writes
# the CalculiX input with its own writer, runs ccx and loads the result. Writes a JSON file
# (argv[-1]) with what the shell test asserts: the mesh's Part link, its group names, every
# warning/error FreeCAD printed, ccx's exit code and the largest x displacement.
import json
import os
import sys
import traceback

import FreeCAD

out = {"console": []}
# Every warning and error FreeCAD's tools print goes through FreeCAD.Console: record them.
for kind in ("PrintWarning", "PrintError"):
    original = getattr(FreeCAD.Console, kind)

    def record(text, _kind=kind, _original=original):
        out["console"].append(f"{_kind}: {text.strip()}")
        _original(text)

    setattr(FreeCAD.Console, kind, record)
try:
    sys.path.insert(0, os.environ["ANISOMESH_MACRO_DIR"])
    import ObjectsFem
    from femtools import ccxtools

    import anisomesh_freecad

    doc = FreeCAD.newDocument("Ccx")
    box = doc.addObject("Part::Box", "Box")
    box.Length, box.Width, box.Height = 40, 10, 10
    analysis = ObjectsFem.makeAnalysis(doc, "Analysis")
    solver = ObjectsFem.makeSolverCalculixCcxTools(doc, "CalculiX")
    solver.AnalysisType = "static"
    solver.GeometricalNonlinearity = "linear"
    solver.SplitInputWriter = False
    analysis.addObject(solver)
    material = ObjectsFem.makeMaterialSolid(doc, "Steel")
    mat = material.Material
    mat.update({"Name": "Steel", "YoungsModulus": "210000 MPa", "PoissonRatio": "0.30"})
    material.Material = mat
    analysis.addObject(material)
    fixed = ObjectsFem.makeConstraintFixed(doc, "Fixed")
    fixed.References = [(box, "Face1")]
    analysis.addObject(fixed)
    doc.recompute()
    along_x = next(f"Edge{i}" for i, e in enumerate(box.Shape.Edges, start=1)
                   if abs(abs((e.Vertexes[1].Point - e.Vertexes[0].Point).normalize().x) - 1) < 1e-9)
    force = ObjectsFem.makeConstraintForce(doc, "Force")
    force.References = [(box, "Face2")]
    force.Force = 1000.0
    force.Direction = (box, [along_x])
    analysis.addObject(force)
    doc.recompute()

    result = anisomesh_freecad.run_blocking(doc, [box], ["--hmax", "4"], analysis)
    mesh_obj = result.obj
    m = mesh_obj.FemMesh
    out.update(part=mesh_obj.Part.Name if getattr(mesh_obj, "Part", None) else None,
               groups=sorted(m.getGroupName(g) for g in m.Groups), tets=m.VolumeCount,
               in_analysis=mesh_obj in analysis.Group, summary=result.summary, warnings=result.warnings)
    # the face groups hold the nodes FreeCAD itself finds on the faces
    out["face_nodes_match"] = {}
    for k, face in enumerate(box.Shape.Faces, start=1):
        gid = next(g for g in m.Groups if m.getGroupName(g) == f"Box_Face{k}")
        out["face_nodes_match"][f"Face{k}"] = sorted(m.getGroupElements(gid)) == sorted(m.getNodesByFace(face))

    fea = ccxtools.FemToolsCcx(analysis, solver)
    fea.update_objects()
    workdir = os.path.join(os.path.dirname(os.path.abspath(sys.argv[-1])), "ccx")
    os.makedirs(workdir, exist_ok=True)
    fea.setup_working_dir(workdir)
    out["prerequisites"] = fea.check_prerequisites()
    fea.write_inp_file()
    out["inp"] = fea.inp_file_name
    out["ccx_exit"] = fea.ccx_run()
    out["ccx_job_finished"] = "Job finished" in (fea.ccx_stdout or "")
    fea.load_results()
    results = [o for o in analysis.Group if o.isDerivedFrom("Fem::FemResultObject")]
    if results:
        out["ux_max"] = max(v.x for v in results[0].DisplacementVectors)
except Exception:  # noqa: BLE001 - reported to the shell test, which fails on it
    out["error"] = traceback.format_exc()
with open(sys.argv[-1], "w") as f:
    json.dump(out, f, indent=1)
sys.exit(0)
