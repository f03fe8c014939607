#pragma once
// Writing meshes. The format comes from the output's extension (any case):
//   .msh  Gmsh MSH 4.1 (ASCII, or binary with `binary`), or MSH 2.2 with mshVersion = 22.
//         4.1: $Entities mirroring the model's topology with our 1-based ids (points =
//         model vertices, curves = edges, surfaces = faces, volumes = solids, each with its
//         bounding entities), nodes in per-entity blocks classified by the entity they lie
//         on, elements per entity. Both versions: physical groups "FACE<n>" (dim 2, tag n),
//         one per solid (dim 3, tag = solid id) named after its part, and one per named
//         face group (dim 2, tag = number of faces + k; 2.2 writes its elements once more).
//   .inp  Abaqus / CalculiX: *NODE, NSET=NALL; volume meshes: C3D4 / C3D10 only, one
//         *ELEMENT block per solid with ELSET=<part>, ELSET=EALL, *NSET FACE<n> and
//         *SURFACE S_FACE<n> (TYPE=ELEMENT, faces S1–S4) per CAD face; surface meshes:
//         S3 / S6 / S4 / S8 with an ELSET and an NSET FACE<n> per face. Both: *NSET
//         EDGE<n> per CAD edge; per named face group *NSET <name> and *SURFACE S_<name>
//         (volume) or *ELSET <name> (surface), after all the others.
//   .vtu  VTK XML unstructured grid (ASCII, or inline base64 with `binary`) with cell data
//         "region" (solid id, 0 for boundary elements), "face" (CAD face id, 0 for
//         tetrahedra) and "quality" (mean ratio; scaled Jacobian for quads); FieldData
//         "region:<part>" and "face:<name>" decoding them (io/VtuWriter.cpp).
//   .unv  I-DEAS universal: datasets 2411, 2412 (91/92 triangles, 94/95 quads, 111/118
//         tetrahedra) and 2467 (a group per face: its nodes and elements; per solid: its
//         tetrahedra; per named face group), as Gmsh writes them (what FreeCAD's FEM
//         importer reads).
// Group names are the same in every format (groupNames, io/OutputMesh.h).
//   .stl .obj .off  through OpenMesh: the surface mesh, for a volume mesh its surface
//         mesh (the boundary and the interfaces between solids); corner nodes only; quads
//         kept in OBJ/OFF, split in two triangles for STL (binary STL with `binary`).
// Quadratic meshes (SurfaceMesh::triangleMid etc. non-empty) give the quadratic element
// types of each format, in that format's node order (io/ElementOrder.h).
// Every writer writes to a temporary file and renames it: no partial file is ever left.
// Throws InputError for an unknown extension or a bad option (node data for a format
// without it), MeshingError for an I/O failure or node data of the wrong size.
#include <string>
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/VolumeMesh.h"

namespace aniso::io {

/// A data array at the nodes written with the mesh (`adapt --transfer`): `components`
/// values per node of the written mesh (all its nodes, mid-edge ones too, in order),
/// node-major. MSH: a $NodeData section (time step 0; Gmsh itself shows 1, 3 or 9
/// components); VTU: a Float64 PointData array.
struct NodeData {
  std::string name;
  int components = 1;
  std::vector<double> values;
};

struct WriteOptions {
  bool binary = false;   ///< MSH, VTU, STL
  int mshVersion = 41;   ///< 41 or 22
  std::vector<NodeData> nodeData;  ///< .msh and .vtu only (InputError for the other formats)
};

void writeSurfaceMesh(const Model& model, const SurfaceMesh& mesh, const std::string& path,
                      const WriteOptions& options = {});
void writeVolumeMesh(const Model& model, const VolumeMesh& mesh, const std::string& path,
                     const WriteOptions& options = {});

}  // namespace aniso::io
