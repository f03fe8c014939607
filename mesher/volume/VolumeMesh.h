#pragma once
// VolumeMesh — the tetrahedral mesh of all solids of a model (thesis ch. 5): what the
// writers consume for 3D output. Index-based (STYLE.md §2-3).
//
// `surface` is the surface mesh the tetrahedra conform to, with its nodes FIRST and in the
// same order (node i of the surface mesh is node i here), so every boundary triangle is a
// face of the tetrahedra: of exactly one tetrahedron on a face bounding one solid, of one
// tetrahedron on each side on a face shared by two solids of an assembly. Nodes created
// inside a solid follow, with NodeOn{Kind::Solid, solid index}. Faces of the model that
// bound no solid (dangling faces) keep their triangles in `surface` but no tetrahedron.
//
// Tetrahedra are positively oriented: (p1 − p0) · ((p2 − p0) × (p3 − p0)) > 0, the order
// Gmsh's type 4 and Abaqus' C3D4 expect.
//
// The exception: a solid whose boundary recovery left triangles out, meshed around those
// holes as a last resort (CarveAroundHoles.h, the solid's outcome degraded): its missing
// triangles are faces of no tetrahedron, and `patchFaces` lists the tetrahedron faces
// that close the holes instead.
#include <array>
#include <string>
#include <vector>

#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

struct VolumeMesh {
  SurfaceMesh surface;                     ///< nodes (all), boundary triangles with their faces
  std::vector<std::array<int, 4>> tets;    ///< positively oriented
  std::vector<int> tetSolid;               ///< 0-based model solid of each tetrahedron
  /// Quadratic tetrahedra (--order 2), empty for linear meshes: tetMid[t][k] is the node on
  /// the edge kTetEdges[k] of tets[t] (shared with surface.triangleMid on the boundary).
  /// Writers permute to their format's order (Gmsh type 11 and Abaqus C3D10 differ).
  std::vector<std::array<int, 6>> tetMid;
  static constexpr int kTetEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  /// Faces of one tetrahedron that are no boundary triangle: the patches closing the holes
  /// of solids meshed around unrecovered triangles (see above). Empty but for those.
  std::vector<std::array<int, 3>> patchFaces;

  const std::vector<Vec3>& nodes() const { return surface.nodes; }

  /// Structural checks, one message per problem: indices in range, positive volumes, no
  /// repeated tetrahedron, every tetrahedron face shared by at most two tetrahedra, every
  /// tetrahedron face used once being a boundary triangle or a patch face. Empty when valid.
  std::vector<std::string> validate() const;
};

}  // namespace aniso
