#pragma once
// Writing meshes. The format comes from the output's extension:
//   .msh  Gmsh MSH 4.1 (ASCII, or binary with `binary`): $Entities mirroring the model's
//         topology with our 1-based ids (points = model vertices, curves = edges, surfaces
//         = faces, each with its bounding entities), nodes in per-entity blocks classified
//         by the entity they lie on, elements per entity, physical groups "FACE<n>" (dim 2)
//   .stl .obj .off  through OpenMesh: the triangles (ASCII; binary STL with `binary`)
// Every writer writes to a temporary file and renames it: no partial file is ever left.
// Throws InputError for an unknown extension, MeshingError for an I/O failure.
#include <string>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso::io {

struct WriteOptions {
  bool binary = false;
};

void writeSurfaceMesh(const Model& model, const SurfaceMesh& mesh, const std::string& path,
                      const WriteOptions& options = {});

void writeMsh41(const Model& model, const SurfaceMesh& mesh, const std::string& path, const WriteOptions& options);
void writeOpenMeshFormat(const SurfaceMesh& mesh, const std::string& path, const WriteOptions& options);

}  // namespace aniso::io
