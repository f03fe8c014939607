#pragma once
// anisomesh.Mesh — the result of anisomesh.mesh() (docs/python.md): the mesh kept in C++
// with its model, so that write() goes through the CLI's io writers (io/MeshWriter.h), and
// NumPy arrays made on access:
//   nodes (N, 3) float64; triangles (M, 3), quads (Q, 4), tetrahedra (K, 4): int64 node
//   indices, 0-based; triangle_faces (M,), quad_faces (Q,): the 1-based CAD face of each
//   element; tetrahedron_solids (K,): the 1-based solid; triangles6 (M, 6), quads8 (Q, 8),
//   tetrahedra10 (K, 10): corners then mid-edge nodes (edges (0,1) (1,2) (2,0) for
//   triangles, (0,1) (1,2) (2,3) (3,0) for quads, (0,1) (1,2) (2,0) (0,3) (1,3) (2,3) for
//   tetrahedra: VTK's and meshio's order), empty unless order 2; parts: {solid id: name}.
//   For a volume mesh, triangles are the boundary and interface triangles of the solids.
#include <pybind11/pybind11.h>

#include <memory>
#include <nlohmann/json.hpp>

#include "mesher/model/Model.h"
#include "mesher/volume/VolumeMesh.h"

namespace aniso::python {

struct MeshData {
  Model model;
  bool volume = false;
  SurfaceMesh surface;  ///< dim 2
  VolumeMesh tets;      ///< dim 3 (its surface holds every node)
  int dim = 2, order = 1;
  std::string status;                 ///< "ok" or "degraded"
  nlohmann::ordered_json report;      ///< the run report (tools/app/MeshRun.h), as --report writes it

  const SurfaceMesh& boundary() const { return volume ? tets.surface : surface; }
};

/// Registers the class anisomesh.Mesh in `m`.
void bindMesh(pybind11::module_& m);

/// A Python Mesh owning `data`.
pybind11::object makeMesh(std::shared_ptr<MeshData> data);

}  // namespace aniso::python
