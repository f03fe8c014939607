#include "tools/python/MeshObject.h"

#include <pybind11/numpy.h>

#include <array>
#include <vector>

#include "io/MeshWriter.h"
#include "mesher/core/Error.h"
#include "tools/python/PyJson.h"

namespace aniso::python {
namespace py = pybind11;
namespace {

using Handle = std::shared_ptr<MeshData>;
using Index = std::int64_t;

py::array_t<double> nodeArray(const std::vector<Vec3>& nodes) {
  py::array_t<double> a({static_cast<py::ssize_t>(nodes.size()), py::ssize_t{3}});
  auto w = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < w.shape(0); ++i)
    for (int k = 0; k < 3; ++k) w(i, k) = nodes[i][k];
  return a;
}

/// Rows of `corners` followed, when `mids` is given, by the row's mid-edge nodes.
template <size_t C, size_t E>
py::array_t<Index> elementArray(const std::vector<std::array<int, C>>& corners,
                                const std::vector<std::array<int, E>>* mids) {
  const py::ssize_t width = C + (mids ? E : 0);
  const py::ssize_t rows = mids && mids->empty() ? 0 : static_cast<py::ssize_t>(corners.size());
  py::array_t<Index> a({rows, width});
  auto w = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < rows; ++i) {
    for (size_t k = 0; k < C; ++k) w(i, k) = corners[i][k];
    if (mids)
      for (size_t k = 0; k < E; ++k) w(i, C + k) = (*mids)[i][k];
  }
  return a;
}

/// 0-based entity indices as 1-based CAD ids.
py::array_t<Index> idArray(const std::vector<int>& index0) {
  py::array_t<Index> a(static_cast<py::ssize_t>(index0.size()));
  auto w = a.mutable_unchecked<1>();
  for (py::ssize_t i = 0; i < w.shape(0); ++i) w(i) = index0[i] + 1;
  return a;
}

const std::vector<std::array<int, 4>> kNoTets;
const std::vector<int> kNoIds;
const std::vector<std::array<int, 6>> kNoTetMids;

const std::vector<std::array<int, 4>>& tets(const MeshData& d) { return d.volume ? d.tets.tets : kNoTets; }

void write(const Handle& d, const std::string& path, bool binary, const std::string& mshVersion) {
  io::WriteOptions o;
  o.binary = binary;
  if (mshVersion == "4.1") o.mshVersion = 41;
  else if (mshVersion == "2.2") o.mshVersion = 22;
  else throw InputError("msh_version must be '4.1' or '2.2', not '" + mshVersion + "'");
  py::gil_scoped_release release;
  if (d->volume) io::writeVolumeMesh(d->model, d->tets, path, o);
  else io::writeSurfaceMesh(d->model, d->surface, path, o);
}

/// meshio.Mesh with the elements of the order and cell data "face" (CAD face, 0 for
/// tetrahedra) and "region" (solid, 0 for surface elements), as the VTU writer names them.
py::object toMeshio(const Handle& d) {
  py::module_ meshio = py::module_::import("meshio");
  py::module_ np = py::module_::import("numpy");
  const SurfaceMesh& s = d->boundary();
  const bool q = d->order == 2;
  py::list cells, face, region;
  auto add = [&](const char* type, py::array block, py::array faces, py::array solids) {
    if (block.shape(0) == 0) return;
    cells.append(py::make_tuple(type, block));
    face.append(faces);
    region.append(solids);
  };
  auto zeros = [&](py::ssize_t n) { return np.attr("zeros")(n, "int64").cast<py::array>(); };
  const py::ssize_t nt = s.triangles.size(), nq = s.quads.size(), nk = tets(*d).size();
  add(q ? "triangle6" : "triangle", q ? elementArray(s.triangles, &s.triangleMid) : elementArray<3, 3>(s.triangles, nullptr),
      idArray(s.triangleFace), zeros(nt));
  add(q ? "quad8" : "quad", q ? elementArray(s.quads, &s.quadMid) : elementArray<4, 4>(s.quads, nullptr),
      idArray(s.quadFace), zeros(nq));
  if (d->volume)
    add(q ? "tetra10" : "tetra", q ? elementArray(d->tets.tets, &d->tets.tetMid) : elementArray<4, 6>(d->tets.tets, nullptr),
        zeros(nk), idArray(d->tets.tetSolid));
  py::dict cellData;
  cellData["face"] = face;
  cellData["region"] = region;
  return meshio.attr("Mesh")(nodeArray(s.nodes), cells, py::arg("cell_data") = cellData);
}

}  // namespace

void bindMesh(py::module_& m) {
  py::class_<MeshData, Handle>(m, "Mesh", "A mesh made by anisomesh.mesh(); arrays are copies made on access")
      .def_property_readonly("dim", [](const MeshData& d) { return d.dim; })
      .def_property_readonly("order", [](const MeshData& d) { return d.order; })
      .def_property_readonly("status", [](const MeshData& d) { return d.status; }, "'ok' or 'degraded'")
      .def_property_readonly("nodes", [](const MeshData& d) { return nodeArray(d.boundary().nodes); })
      .def_property_readonly("triangles", [](const MeshData& d) { return elementArray<3, 3>(d.boundary().triangles, nullptr); })
      .def_property_readonly("triangle_faces", [](const MeshData& d) { return idArray(d.boundary().triangleFace); })
      .def_property_readonly("quads", [](const MeshData& d) { return elementArray<4, 4>(d.boundary().quads, nullptr); })
      .def_property_readonly("quad_faces", [](const MeshData& d) { return idArray(d.boundary().quadFace); })
      .def_property_readonly("tetrahedra", [](const MeshData& d) { return elementArray<4, 6>(tets(d), nullptr); })
      .def_property_readonly("tetrahedron_solids",
                             [](const MeshData& d) { return idArray(d.volume ? d.tets.tetSolid : kNoIds); })
      .def_property_readonly("triangles6",
                             [](const MeshData& d) { return elementArray(d.boundary().triangles, &d.boundary().triangleMid); })
      .def_property_readonly("quads8", [](const MeshData& d) { return elementArray(d.boundary().quads, &d.boundary().quadMid); })
      .def_property_readonly("tetrahedra10",
                             [](const MeshData& d) { return elementArray(tets(d), d.volume ? &d.tets.tetMid : &kNoTetMids); })
      .def_property_readonly("parts",
                             [](const MeshData& d) {
                               py::dict parts;
                               for (size_t i = 0; i < d.model.solids.size(); ++i) parts[py::int_(i + 1)] = d.model.solids[i].name;
                               return parts;
                             },
                             "{solid id (1-based): part name}")
      .def_property_readonly("problems", [](const MeshData& d) { return toPython(d.report["problems"]); },
                             "[{entity, kind, id, part, severity, code, detail, phase}]")
      .def_property_readonly("report", [](const MeshData& d) { return toPython(d.report); },
                             "The run report: the JSON the CLI's --report writes")
      .def("write", &write, py::arg("path"), py::arg("binary") = false, py::arg("msh_version") = "4.1",
           "Writes the mesh by the extension of path (.msh .inp .vtu .unv .stl .obj .off), as the CLI does")
      .def("to_meshio", &toMeshio, "The mesh as a meshio.Mesh (needs meshio)")
      .def("__repr__", [](const MeshData& d) {
        const SurfaceMesh& s = d.boundary();
        return "<anisomesh.Mesh dim " + std::to_string(d.dim) + ", order " + std::to_string(d.order) + ", " +
               std::to_string(s.nodes.size()) + " nodes, " + std::to_string(s.triangles.size()) + " triangles, " +
               std::to_string(s.quads.size()) + " quads, " + std::to_string(tets(d).size()) + " tetrahedra, " + d.status + ">";
      });
}

py::object makeMesh(std::shared_ptr<MeshData> data) { return py::cast(std::move(data)); }

}  // namespace aniso::python
