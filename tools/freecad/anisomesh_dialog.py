# The macro's dialog (FreeCAD GUI): the options a FEM user sets, with the CLI's own defaults
# (anisomesh_options.cli_defaults: read from `anisomesh mesh --help`, sizes scaled by the
# selection's bounding box as the CLI scales them), tooltips naming the CLI option; the CLI
# runs in the background (QProcess) with a progress bar fed by its progress lines; at the end
# the dialog stays open with a one-line summary and the warnings (also printed to FreeCAD's
# report view); on failure the CLI's message is shown and nothing is created.
import os
import re
import shlex
import shutil
import tempfile

import FreeCAD

import anisomesh_freecad as core
from anisomesh_options import build_command, cli_defaults, dialog_defaults, failure_message, options_from_settings

PROGRESS = re.compile(r"^progress: (.+?) (\d+)%\s*(.*)$")


def open_for_selection():
    """Opens the dialog for the selected objects with a shape; returns it (None when there is
    nothing to mesh or the CLI cannot be found: a message box says why)."""
    import FreeCADGui
    from PySide import QtGui

    doc = FreeCAD.ActiveDocument
    objects = [o for o in FreeCADGui.Selection.getSelection() if hasattr(o, "Shape")]
    if doc is None or not objects:
        QtGui.QMessageBox.warning(None, "AnisoMesh", "Select one or more Part objects to mesh.")
        return None
    try:
        import FemGui
        active = FemGui.getActiveAnalysis()
    except Exception:  # noqa: BLE001 - no FEM GUI: no active analysis
        active = None
    try:
        cli = core.find_cli()
        dialog = MeshDialog(doc, objects, cli, cli_defaults(cli), core.find_analysis(doc, active))
    except Exception as e:  # noqa: BLE001 - no CLI, a CLI that does not run, an object without shape
        QtGui.QMessageBox.critical(None, "AnisoMesh", f"cannot mesh the selection: {e}")
        return None
    dialog.widget.show()
    return dialog


class MeshDialog:
    """The dialog and its run. Attributes used by the tests: widget (the QDialog), fields
    ({key: input widget}), shown (the defaults shown), summary, warnings (QLabel, QPlainTextEdit),
    result (core.Result after a successful run)."""

    def __init__(self, doc, objects, cli, defaults, analysis):
        import FreeCADGui
        from PySide import QtGui

        self.doc, self.objects, self.cli, self.analysis = doc, objects, cli, analysis
        self.shapes = core.shapes_of(objects)
        self.has_solids = any(s.Solids for s in self.shapes)
        diag = core.diagonal_of(self.shapes)
        self.shown = dialog_defaults(defaults, diag)
        self.proc = self.folder = self.result = None
        self.stderr = ""
        self.options = []

        w = self.widget = QtGui.QDialog(FreeCADGui.getMainWindow())
        w.setWindowTitle("AnisoMesh: " + ", ".join(o.Label for o in objects))
        form = QtGui.QFormLayout(w)
        self.fields = {}

        def size(key, label, tip, special=None):
            box = QtGui.QDoubleSpinBox()
            box.setRange(0.0, 1e9)
            box.setDecimals(5)
            box.setSingleStep(max(diag / 100, 1e-3))
            box.setSuffix(" mm")
            if special:
                box.setSpecialValueText(special)
            box.setValue(self.shown[key] or 0.0)
            if self.shown[key] is not None:
                self.shown[key] = box.value()  # as displayed: an untouched field is not sent
            box.setToolTip(tip)
            form.addRow(label, box)
            self.fields[key] = box

        size("size", "Element size", "Target element size everywhere (--size). Curved faces and thin parts still "
             "get smaller elements. Automatic: the max size, refined by curvature.", special="automatic")
        size("hmax", "Max element size", f"Largest element size (--hmax), a bound every size source respects. "
             f"Default: {defaults.get('--hmax-rel', '?')} × the selection's bounding-box diagonal ({diag:.4g} mm).",
             special="none")
        size("hmin", "Min element size", f"Smallest element size (--hmin), a bound every size source respects. "
             f"Default: {defaults.get('--hmin-rel', '?')} × the bounding-box diagonal.", special="none")
        circle = QtGui.QSpinBox()
        circle.setRange(3, 360)
        circle.setValue(int(self.shown["elements_per_circle"] or 12))
        circle.setToolTip("Curvature: elements per full circle on curved faces and edges "
                          "(--elements-per-circle, as Gmsh's -clcurv).")
        form.addRow("Elements per circle", circle)
        self.fields["elements_per_circle"] = circle
        order = QtGui.QComboBox()
        order.addItems(["1 - linear (C3D4, S3)", "2 - quadratic (C3D10, S6)"])
        order.setCurrentIndex((self.shown["order"] or 1) - 1)
        order.setToolTip("Element order (--order); quadratic mid-edge nodes lie on the CAD surfaces.")
        form.addRow("Element order", order)
        self.fields["order"] = order
        kind = QtGui.QComboBox()
        kind.addItems(["Volume (tetrahedra)", "Surface only (shells)"])
        kind.setCurrentIndex(0 if self.has_solids else 1)
        kind.setEnabled(self.has_solids)
        kind.setToolTip("Volume mesh of the solids, or only their surface (--dim 2) for shell elements.")
        form.addRow("Mesh", kind)
        self.fields["surface"] = kind
        quad = QtGui.QCheckBox("Quad-dominant (surface mesh)")
        quad.setToolTip("Quadrilaterals where they fit, triangles elsewhere (--quad): a surface mesh of S4/S8 shells.")
        quad.toggled.connect(lambda on: (kind.setCurrentIndex(1) if on else None, kind.setEnabled(self.has_solids and not on)))
        form.addRow("", quad)
        self.fields["quad"] = quad
        extra = QtGui.QLineEdit()
        extra.setPlaceholderText("e.g. --gradation 2")
        extra.setToolTip("Further anisomesh options as on the command line (anisomesh mesh --help).")
        form.addRow("More options", extra)
        self.fields["extra"] = extra

        self.bar = QtGui.QProgressBar()
        self.bar.setRange(0, 100)
        self.bar.setVisible(False)
        self.status = QtGui.QLabel("")
        self.summary = QtGui.QLabel("")
        self.summary.setWordWrap(True)
        self.warnings = QtGui.QPlainTextEdit()
        self.warnings.setReadOnly(True)
        self.warnings.setVisible(False)
        for row in (self.bar, self.status, self.summary, self.warnings):
            form.addRow(row)
        self.buttons = QtGui.QDialogButtonBox(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)
        self.buttons.button(QtGui.QDialogButtonBox.Ok).setText("Mesh")
        form.addRow(self.buttons)
        self.buttons.accepted.connect(self.start)
        self.buttons.rejected.connect(self.cancel)

    def settings(self):
        """The dialog's values as anisomesh_options.options_from_settings takes them."""
        f = self.fields
        return {"size": f["size"].value() or None, "hmax": f["hmax"].value() or None, "hmin": f["hmin"].value() or None,
                "elements_per_circle": f["elements_per_circle"].value() or None,
                "order": f["order"].currentIndex() + 1, "quad": f["quad"].isChecked(),
                "surface": self.has_solids and f["surface"].currentIndex() == 1,
                "extra": shlex.split(f["extra"].text())}

    def _busy(self, busy):
        from PySide import QtGui

        self.buttons.button(QtGui.QDialogButtonBox.Ok).setEnabled(not busy)
        for box in self.fields.values():
            box.setEnabled(not busy)
        if not busy:
            self.fields["surface"].setEnabled(self.has_solids and not self.fields["quad"].isChecked())

    def _show_warnings(self, lines, error=False):
        self.warnings.setPlainText("\n".join(lines))
        self.warnings.setVisible(bool(lines))
        self.warnings.setStyleSheet("color: #b00000;" if error else "")
        self.widget.adjustSize()

    def start(self):
        from PySide import QtCore

        try:
            self.options = options_from_settings(self.settings(), self.shown)
            self.folder = tempfile.mkdtemp(prefix="anisomesh-")
            brep = core.export_shapes(self.shapes, self.folder)
        except Exception as e:  # noqa: BLE001 - shown in the dialog
            self._failed(str(e))
            return
        cmd = build_command(self.cli, brep, os.path.join(self.folder, "mesh.unv"),
                            os.path.join(self.folder, "report.json"), self.options)
        self.proc, self.stderr = QtCore.QProcess(self.widget), ""
        self.proc.readyReadStandardError.connect(self._on_stderr)
        self.proc.finished.connect(self._on_finished)
        self._busy(True)
        self.bar.setValue(0)
        self.bar.setVisible(True)
        self._show_warnings([])
        self.summary.setText("")
        self.status.setText("meshing: " + " ".join(self.options) if self.options else "meshing with the defaults")
        self.proc.start(cmd[0], cmd[1:])

    def _on_stderr(self):
        text = bytes(self.proc.readAllStandardError()).decode("utf-8", "replace")
        self.stderr += text
        for line in text.splitlines():
            m = PROGRESS.match(line)
            if m:
                self.bar.setValue(int(m.group(2)))
                self.status.setText(f"{m.group(1)} {m.group(3)}".strip())

    def _cleanup(self):
        if self.folder:
            shutil.rmtree(self.folder, ignore_errors=True)
        self.folder, self.proc = None, None

    def _failed(self, message):
        FreeCAD.Console.PrintError(f"anisomesh: {message}\n")
        self._cleanup()
        self._busy(False)
        self.status.setText("failed: nothing was created")
        self._show_warnings([message], error=True)

    def _on_finished(self, code, _status=None):
        if code != 0:
            self._failed(failure_message(code, self.stderr, os.path.join(self.folder, "report.json")))
            return
        try:
            self.result = core.finish_run(self.doc, self.objects, self.shapes, self.folder, self.stderr,
                                          self.options, self.analysis)
        except Exception as e:  # noqa: BLE001 - shown in the dialog, nothing created
            self._failed(str(e))
            return
        from PySide import QtGui

        self._cleanup()
        self.bar.setValue(100)
        self.status.setText("done")
        self.summary.setText(self.result.summary)
        self._show_warnings([f"warning: {w}" for w in self.result.warnings])
        for w in self.result.warnings:
            FreeCAD.Console.PrintWarning(f"anisomesh: {w}\n")
        FreeCAD.Console.PrintMessage(f"anisomesh: {self.result.summary}\n")
        self.buttons.button(QtGui.QDialogButtonBox.Ok).setVisible(False)
        self.buttons.button(QtGui.QDialogButtonBox.Cancel).setText("Close")

    def cancel(self):
        if self.proc is not None:
            self.proc.kill()
            self.proc.waitForFinished(3000)
        self._cleanup()
        self.widget.reject()
