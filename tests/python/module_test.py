"""The Python module (tools/python, docs/python.md) against the CLI.

usage: module_test.py ANISOMESH_CLI OWN_MODELS_DIR SHARED_MODELS_DIR   (PYTHONPATH: build/python)
The mesh the module writes is the CLI's, byte for byte (bracket 3D and 2D; periodic_u_cst,
whose 3D run at the thesis' sizing keeps one proximity round; blocks2, whose run at the
thesis' sizing keeps the coarse-solid retry); the arrays are the mesh
(shapes, 0-based, positive volumes, CAD ids); bad input raises InputError, a time limit
MeshingError with its problems; progress is reported and Ctrl-C stops a run.
"""
import _thread
import os
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np

import anisomesh

CLI, OWN, SHARED = sys.argv[1:4]
BRACKET = os.path.join(OWN, "bracket.step")
PERIODIC = os.path.join(SHARED, "periodic_u_cst.step")
BLOCKS2 = os.path.join(OWN, "blocks2.step")


def read(path):
    with open(path, "rb") as f:
        return f.read()


class SameAsCli(unittest.TestCase):
    """anisomesh mesh MODEL -o x.msh [options] and anisomesh.mesh(MODEL, ...).write(y.msh)."""

    def same(self, model, cli_args, **kwargs):
        with tempfile.TemporaryDirectory() as d:
            x, y = os.path.join(d, "x.msh"), os.path.join(d, "y.msh")
            subprocess.run([CLI, "mesh", model, "-o", x, "-q"] + cli_args, check=True)
            m = anisomesh.mesh(model, **kwargs)
            m.write(y)
            self.assertGreater(os.path.getsize(x), 1000)
            self.assertEqual(read(x), read(y), f"{model} {cli_args}: the module's mesh differs from the CLI's")
            return m

    def test_bracket_volume(self):
        m = self.same(BRACKET, [])
        self.assertEqual(m.dim, 3)
        self.assertGreater(len(m.tetrahedra), 1000)

    def test_bracket_surface(self):
        m = self.same(BRACKET, ["--dim", "2"], dim=2)
        self.assertEqual(m.tetrahedra.shape, (0, 4))
        self.assertGreater(len(m.triangles), 500)

    def test_proximity_round(self):
        m = self.same(PERIODIC, ["--hmax-rel", "0.5", "--curvature-ratio", "0.15"], hmax_rel=0.5, curvature_ratio=0.15)
        self.assertEqual(m.report["proximity"]["rounds"], 1)  # the round is the point of this case

    def test_coarse_solid_retry(self):
        thesis = ["--hmax-rel", "0.5", "--curvature-ratio", "0.15", "--chord-deviation-rel", "0"]
        m = self.same(BLOCKS2, thesis, hmax_rel=0.5, curvature_ratio=0.15, chord_deviation_rel=0)
        self.assertTrue(m.report["coarse_solids"]["refined_kept"])  # the retry is the point of this case

    def test_chord_deviation(self):
        off = self.same(BRACKET, ["--dim", "2", "--chord-deviation-rel", "0"], dim=2, chord_deviation_rel=0)
        on = anisomesh.mesh(BRACKET, dim=2)  # the default bounds the chords: more triangles
        self.assertGreater(len(on.triangles), len(off.triangles))

    def test_crack(self):
        crack = os.path.join(OWN, "crack.brep")
        m = self.same(crack, ["--hmax", "1.5"], hmax=1.5)
        bonded = self.same(crack, ["--hmax", "1.5", "--internal-faces", "bond"], hmax=1.5, internal_faces="bond")
        doubled = m.report["cracks"]["nodes_duplicated"]
        self.assertGreater(doubled, 0)
        self.assertEqual(bonded.report["cracks"]["faces"], 0)
        with self.assertRaises(anisomesh.InputError):
            anisomesh.mesh(crack, internal_faces="open")

    def test_other_formats(self):
        m = anisomesh.mesh(BRACKET, dim=2)
        with tempfile.TemporaryDirectory() as d:
            for ext in ("inp", "vtu"):
                x, y = os.path.join(d, "x." + ext), os.path.join(d, "y." + ext)
                subprocess.run([CLI, "mesh", BRACKET, "-o", x, "-q", "--dim", "2"], check=True)
                m.write(y)
                self.assertEqual(read(x), read(y), ext)


class AdaptSameAsCli(unittest.TestCase):
    """anisomesh adapt and anisomesh.adapt() on a tanh front sampled on a first mesh of the cube."""

    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()
        cls.cube = os.path.join(OWN, "cube.step")
        first = anisomesh.mesh(cls.cube, size=1)
        x = first.nodes / 10.0
        f = np.tanh(50 * (((x - 0.5) ** 2).sum(1) - 0.09))
        cls.field = os.path.join(cls.dir.name, "f.vtu")
        tets = first.tetrahedra
        with open(cls.field, "w") as out:  # an ASCII VTU, as ParaView writes one
            out.write('<VTKFile type="UnstructuredGrid" version="1.0"><UnstructuredGrid>'
                      f'<Piece NumberOfPoints="{len(x)}" NumberOfCells="{len(tets)}"><PointData>'
                      '<DataArray type="Float64" Name="f" format="ascii">' + " ".join(map(repr, f)) +
                      '</DataArray></PointData><Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">' +
                      " ".join(map(repr, first.nodes.ravel())) + '</DataArray></Points><Cells>'
                      '<DataArray type="Int64" Name="connectivity" format="ascii">' + " ".join(map(str, tets.ravel())) +
                      '</DataArray><DataArray type="Int64" Name="offsets" format="ascii">' +
                      " ".join(str(4 * (i + 1)) for i in range(len(tets))) +
                      '</DataArray><DataArray type="UInt8" Name="types" format="ascii">' + " 10" * len(tets) +
                      '</DataArray></Cells></Piece></UnstructuredGrid></VTKFile>\n')

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def test_count_rounds_as_the_cli(self):
        x, y = os.path.join(self.dir.name, "x.msh"), os.path.join(self.dir.name, "y.msh")
        subprocess.run([CLI, "adapt", self.cube, "--from", self.field, "--field", "f", "-o", x, "--target-nodes", "3000",
                        "-q"], check=True)
        m = anisomesh.adapt(self.cube, from_mesh=self.field, field="f", target_nodes=3000)
        m.write(y)
        self.assertEqual(read(x), read(y), "the module's adapted mesh differs from the CLI's")
        count = m.report["adapt"]["count"]
        self.assertEqual(count["made"], len(m.nodes))
        self.assertGreaterEqual(count["meshes"], 1)

    def test_bad_field(self):
        with self.assertRaises(anisomesh.InputError) as e:
            anisomesh.adapt(self.cube, from_mesh=self.field, field="nope", target_nodes=100)
        self.assertIn("nope", str(e.exception))
        with self.assertRaises(anisomesh.InputError):
            anisomesh.adapt(self.cube, from_mesh=self.field, field="f", target_nodes=100, error=0.1)


class Arrays(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.info = anisomesh.info(BRACKET, faces=True)
        cls.mesh = anisomesh.mesh(BRACKET)

    def test_shapes_and_indices(self):
        m = self.mesh
        nodes, tets, tris = m.nodes, m.tetrahedra, m.triangles
        self.assertEqual(nodes.dtype, np.float64)
        self.assertEqual(nodes.shape, (self.mesh.report["counts"]["nodes"], 3))
        self.assertEqual(tets.shape, (m.report["counts"]["tetrahedra"], 4))
        self.assertEqual(tris.shape[1], 3)
        for a in (tets, tris):
            self.assertTrue(np.issubdtype(a.dtype, np.integer))
            self.assertEqual(a.min(), 0)  # 0-based
            self.assertLess(a.max(), len(nodes))
        self.assertEqual(m.quads.shape, (0, 4))
        self.assertEqual(m.tetrahedra10.shape, (0, 10))  # order 1

    def test_volumes_positive_and_sum_to_the_part(self):
        p = self.mesh.nodes[self.mesh.tetrahedra]
        vol = np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6
        self.assertGreater(vol.min(), 0)
        self.assertAlmostEqual(vol.sum() / self.info["volume"], 1, delta=0.01)

    def test_groups(self):
        m = self.mesh
        self.assertEqual(m.parts, {1: self.info["solid_list"][0]["name"]})
        self.assertTrue((m.tetrahedron_solids == 1).all())
        faces = m.triangle_faces
        self.assertEqual(faces.shape, (len(m.triangles),))
        self.assertEqual(set(faces.tolist()), set(range(1, self.info["faces"] + 1)))  # 1-based CAD ids, every face

    def test_report_and_problems(self):
        r = self.mesh.report
        self.assertEqual(r["status"], "ok")
        self.assertEqual(self.mesh.status, "ok")
        self.assertEqual(r["options"]["dim"], 3)
        self.assertEqual(r["options"]["anisotropy"], 1.0)  # the CLI's volume default
        self.assertEqual(r["input"], BRACKET)
        for key in ("counts", "quality", "model", "volume", "solids", "stages", "sizing"):
            self.assertIn(key, r)
        self.assertEqual(self.mesh.problems, r["problems"])
        self.assertIsInstance(self.mesh.problems, list)

    def test_info(self):
        i = self.info
        self.assertEqual(i["solids"], 1)
        self.assertGreater(i["volume"], 0)
        self.assertEqual(len(i["face_list"]), i["faces"])
        self.assertEqual(i["units"], "mm")
        self.assertIn("prepared", i)

    def test_quadratic(self):
        m = anisomesh.mesh(BRACKET, dim=2, order=2)
        t6 = m.triangles6
        self.assertEqual(t6.shape, (len(m.triangles), 6))
        self.assertTrue((t6[:, :3] == m.triangles).all())
        self.assertTrue(set(t6[:, 3:].ravel().tolist()).isdisjoint(m.triangles.ravel().tolist()))

    def test_meshio(self):
        try:
            import meshio  # noqa: F401
        except ImportError:
            self.skipTest("meshio not importable")
        mm = self.mesh.to_meshio()
        self.assertEqual(mm.points.shape, self.mesh.nodes.shape)
        types = [c.type for c in mm.cells]
        self.assertEqual(types, ["triangle", "tetra"])
        self.assertEqual(len(mm.cell_data["region"][1]), len(self.mesh.tetrahedra))


class Errors(unittest.TestCase):
    def test_missing_file(self):
        with self.assertRaises(anisomesh.InputError) as c:
            anisomesh.mesh("/nonexistent/part.step")
        self.assertIsInstance(c.exception, anisomesh.Error)
        self.assertEqual(c.exception.problems, [])

    def test_not_cad(self):
        with tempfile.NamedTemporaryFile("w", suffix=".step") as f:
            f.write("not a STEP file\n")
            f.flush()
            with self.assertRaises(anisomesh.InputError):
                anisomesh.mesh(f.name)
            with self.assertRaises(anisomesh.InputError):
                anisomesh.info(f.name)

    def test_bad_options(self):
        with self.assertRaises(anisomesh.InputError):
            anisomesh.mesh(BRACKET, size=2, hmax=3)
        with self.assertRaises(anisomesh.InputError):
            anisomesh.mesh(BRACKET, dim=3, quad=True)
        with self.assertRaises(anisomesh.InputError):
            anisomesh.mesh(BRACKET, dim=2).write("/tmp/mesh.xyz")

    def test_time_limit(self):
        with self.assertRaises(anisomesh.MeshingError) as c:
            anisomesh.mesh(BRACKET, size=0.5, time_limit=0.05)
        self.assertEqual(c.exception.problems[-1]["code"], "time-limit")
        self.assertEqual(c.exception.report["status"], "failed")


class Progress(unittest.TestCase):
    def test_phases_reported(self):
        calls = []
        anisomesh.mesh(BRACKET, progress=lambda *a: calls.append(a))
        phases = {c[0] for c in calls}
        self.assertTrue({"read", "prepare"} <= phases, phases)
        self.assertTrue(any(c[3] == "end" for c in calls))
        self.assertTrue(all(len(c) == 4 for c in calls))
        self.assertTrue(all(c[1] <= c[2] or c[2] == 0 for c in calls), calls[:10])

    def test_callback_exception_stops_the_run(self):
        def stop(*_):
            raise RuntimeError("stop here")
        with self.assertRaisesRegex(RuntimeError, "stop here"):
            anisomesh.mesh(BRACKET, progress=stop)


class CtrlC(unittest.TestCase):
    def test_keyboard_interrupt_stops_a_long_run(self):
        timer = threading.Timer(0.5, _thread.interrupt_main)
        t0 = time.monotonic()
        timer.start()
        with self.assertRaises(KeyboardInterrupt):
            anisomesh.mesh(BRACKET, size=0.4)  # tens of seconds when not stopped
        self.assertLess(time.monotonic() - t0, 5)
        self.assertEqual(anisomesh.mesh(BRACKET, dim=2).status, "ok")  # the module is usable afterwards


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
