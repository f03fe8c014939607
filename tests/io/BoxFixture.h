#pragma once
// Hand-made meshes for the writer tests: a box [0,L]×[0,W]×[0,H] with the topology of
// OCCT's box (faces 1..6 at x = 0, x = L, y = 0, y = W, z = 0, z = H), split into a grid
// of cells, each cell into the 6 Kuhn (Freudenthal) tetrahedra around its diagonal; and
// the box's surface as quads (faces 1–5) and triangles (face 6).
#include <array>
#include <string>

#include "mesher/model/Model.h"
#include "mesher/volume/VolumeMesh.h"

namespace aniso::testing {

/// The box's model: 8 vertices, 12 edges, 6 faces (outward normals, not reversed), one
/// closed shell, one solid named `name`. No geometry (curves and surfaces are null).
Model boxModel(const Vec3& size, const std::string& name);

/// The tetrahedral mesh: surface nodes first, then interior nodes; boundary triangles
/// oriented outward; with `quadratic`, mid-edge nodes on every edge (tetMid, triangleMid).
VolumeMesh boxTets(const Vec3& size, const std::array<int, 3>& cells, bool quadratic);

/// The box's surface: faces 1–5 as quads of the grid, face 6 as two triangles per cell;
/// with `quadratic`, mid-edge nodes (quadMid, triangleMid).
SurfaceMesh boxSurface(const Vec3& size, const std::array<int, 3>& cells, bool quadratic);

/// Appends `b` to `a` (its model entities and nodes renumbered after a's), translated by
/// `shift`: several disjoint solids in one model.
void appendShifted(Model& a, VolumeMesh& am, const Model& b, const VolumeMesh& bm, const Vec3& shift);

}  // namespace aniso::testing
