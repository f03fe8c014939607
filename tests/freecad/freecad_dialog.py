# Run by freecad_dialog_test.sh inside the FreeCAD GUI (under Xvfb): opens the macro's dialog
# on a selected plate with a hole and a pin through its solid part (an overlap: a warning),
# saves a screenshot, records the values it shows and the
# options an untouched dialog would send, presses "Mesh", waits for the run, saves a second
# screenshot and records the summary, the warnings and the new FemMeshObject. Writes
# dialog.json into $ANISOMESH_TEST_OUT and leaves FreeCAD.
import json
import os
import sys
import time
import traceback

import FreeCAD
import FreeCADGui
from PySide import QtGui

out_dir = os.environ["ANISOMESH_TEST_OUT"]
out = {}
try:
    sys.path.insert(0, os.environ["ANISOMESH_MACRO_DIR"])
    import ObjectsFem

    import anisomesh_dialog
    from anisomesh_options import options_from_settings

    doc = FreeCAD.newDocument("Dialog")
    b = doc.addObject("Part::Box", "PlateBox")
    b.Length, b.Width, b.Height = 40, 20, 10
    c = doc.addObject("Part::Cylinder", "Hole")
    c.Radius, c.Height = 4, 10
    c.Placement.Base = FreeCAD.Vector(20, 10, 0)
    plate = doc.addObject("Part::Cut", "Plate")
    plate.Base, plate.Tool = b, c
    pin = doc.addObject("Part::Cylinder", "Pin")
    pin.Radius, pin.Height = 2, 14
    pin.Placement.Base = FreeCAD.Vector(8, 10, -2)
    ObjectsFem.makeAnalysis(doc, "Analysis")
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(plate)
    FreeCADGui.Selection.addSelection(pin)

    dlg = anisomesh_dialog.open_for_selection()
    QtGui.QApplication.processEvents()
    f = dlg.fields
    out["shown"] = {"size": f["size"].value(), "hmax": f["hmax"].value(), "hmin": f["hmin"].value(),
                    "elements_per_circle": f["elements_per_circle"].value(),
                    "order": f["order"].currentIndex() + 1, "quad": f["quad"].isChecked(),
                    "surface": f["surface"].currentIndex() == 1}
    box = FreeCAD.BoundBox(plate.Shape.BoundBox)
    box.add(pin.Shape.BoundBox)
    out["diagonal"] = box.DiagonalLength
    out["untouched_options"] = options_from_settings(dlg.settings(), dlg.shown)
    out["tooltips"] = {k: w.toolTip() for k, w in f.items()}
    out["labels"] = [dlg.widget.layout().itemAt(i, QtGui.QFormLayout.LabelRole).widget().text()
                     for i in range(dlg.widget.layout().rowCount())
                     if dlg.widget.layout().itemAt(i, QtGui.QFormLayout.LabelRole)]
    out["screenshot_before"] = os.path.join(out_dir, "dialog_before.png")
    dlg.widget.grab().save(out["screenshot_before"])

    dlg.buttons.button(QtGui.QDialogButtonBox.Ok).click()
    deadline = time.time() + 120
    while dlg.result is None and dlg.proc is not None and time.time() < deadline:
        QtGui.QApplication.processEvents()
        time.sleep(0.02)
    QtGui.QApplication.processEvents()
    out["screenshot_after"] = os.path.join(out_dir, "dialog_after.png")
    dlg.widget.grab().save(out["screenshot_after"])
    out["summary"] = dlg.summary.text()
    out["warnings_text"] = dlg.warnings.toPlainText()
    meshes = [o for o in doc.Objects if o.TypeId == "Fem::FemMeshObject"]
    out["meshes"] = len(meshes)
    if meshes:
        m = meshes[0]
        out["part"] = m.Part.Name
        out["in_analysis"] = m in doc.getObject("Analysis").Group
        out["groups"] = sorted(m.FemMesh.getGroupName(g) for g in m.FemMesh.Groups)
except Exception:  # noqa: BLE001 - reported to the shell test, which fails on it
    out["error"] = traceback.format_exc()
with open(os.path.join(out_dir, "dialog.json"), "w") as fh:
    json.dump(out, fh, indent=1)
os._exit(0)  # leave the GUI without its "save changes?" questions
