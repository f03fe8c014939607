#pragma once
// PatchMesh — the solver's mesh a field lives on, as the adaptation sees it (issue 19):
// nodes and the cells of the top dimension (tetrahedra in 3D, triangles on a surface),
// linear or quadratic: a cell lists its corners first (3 or 4), then any other nodes.
// Built by the caller from a mesh file; no file formats here.
#include <array>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

struct PatchMesh {
  int dim = 3;  ///< 3: cells are tetrahedra; 2: triangles (a surface in space)
  std::vector<Vec3> nodes;
  std::vector<int> offsets{0};  ///< cell i: conn[offsets[i] .. offsets[i+1])
  std::vector<int> conn;

  std::size_t cellCount() const { return offsets.size() - 1; }
  int corners() const { return dim + 1; }
};

/// A facet on the boundary of the cells' union: a triangle of a tet mesh (dim 3), an edge
/// of a triangle mesh (dim 2; nodes[2] = −1).
struct BoundaryFacet {
  std::array<int, 3> nodes{-1, -1, -1};
  double measure = 0;              ///< area (dim 3), length (dim 2)
  Vec3 direction = Vec3::Zero();   ///< unit normal (dim 3), unit tangent (dim 2)
};
std::vector<BoundaryFacet> boundaryFacets(const PatchMesh& m);

/// The nodes sharing a cell with each node (sorted, without the node itself).
std::vector<std::vector<int>> nodeNeighbours(const PatchMesh& m);
/// 1 for the nodes on the boundary of the cells' union (on a facet — corner triple of a tet,
/// corner pair of a triangle — that only one cell has; a quadratic cell's other nodes on it too).
std::vector<char> boundaryNodes(const PatchMesh& m);
/// The volume (dim 3) or area (dim 2) of cell c's corner simplex.
double cellMeasure(const PatchMesh& m, std::size_t c);
/// The lumped measure of every node: each cell's volume (area) shared equally by its corners.
std::vector<double> nodeMeasures(const PatchMesh& m);
/// Orthonormal t1, t2 with (t1, t2, n) right-handed, for a unit normal n.
void tangentFrame(const Vec3& n, Vec3& t1, Vec3& t2);
/// Per node, a unit normal for dim 2 (area-weighted mean of its triangles'; zero when they
/// cancel); empty for dim 3.
std::vector<Vec3> nodeNormals(const PatchMesh& m);

}  // namespace aniso
