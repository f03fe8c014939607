#pragma once
// checkSurfaceGeometry — the geometric postcondition of the surface repair stage
// (SurfaceRepair.h), a validator tests call (SurfaceMesh::validate checks combinatorics
// only): no folded edge (UnfoldSurface.h's measure: two triangles of one face whose
// normals are more than about 84 degrees apart), no flat triangle (twice its area below
// kFlatTriangleRatio times its longest edge squared), closed where the shells are closed:
// the triangles and quads of every solid whose faces all have elements use each edge an
// even number of times (a face its shells list twice counts twice), and not crossing
// itself near the CAD edges: two triangles around a node on a CAD vertex or edge (where
// the chords of two faces meet and can pass through each other: a wedge narrower than
// their sagitta) meet nowhere but in the nodes and edge they share (exact predicates,
// SegmentCrossing.h; a node of one strictly inside the other counts as a crossing).
#include <string>
#include <utility>
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

/// A triangle is flat when its height over its longest edge is below this (a relative
/// measure: a triangle with a 179.99 degree angle still has about 1e-4).
inline constexpr double kFlatTriangleRatio = 1e-8;

struct SurfaceGeometryCheck {
  int foldedEdges = 0;
  int flatTriangles = 0;
  long long openEdges = 0;  ///< edges of closed solids' shells used an odd number of times
  int crossingPairs = 0;    ///< pairs of triangles around a CAD vertex or edge node that cross
  std::vector<std::pair<int, int>> foldedFaces;  ///< (0-based face, folded edges), by face
  std::vector<std::pair<int, int>> flatFaces;    ///< (0-based face, flat triangles), by face
  std::vector<std::pair<int, long long>> openSolids;  ///< (0-based solid, open edges), by solid
  std::vector<std::pair<int, int>> crossingFaces;     ///< (0-based face, crossing pairs it is in), by face
  bool ok() const { return foldedEdges == 0 && flatTriangles == 0 && openEdges == 0 && crossingPairs == 0; }
  /// One line per kind of finding; empty when ok().
  std::vector<std::string> messages() const;
};

/// Checks the linear triangles of `mesh` (quads and mid nodes are not looked at).
SurfaceGeometryCheck checkSurfaceGeometry(const Model& model, const SurfaceMesh& mesh);

}  // namespace aniso
