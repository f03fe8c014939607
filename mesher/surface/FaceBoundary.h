#pragma once
// The boundary of one face in its parametric plane, as the contour discretization
// (thesis alg. 4.1) hands it to the face mesher, and the face mesher's result.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

struct BoundaryNode {
  Vec2 uv;
  int node = -1;  ///< global SurfaceMesh node
  /// The node's 3D position where it is not p(uv): the copies of a vertex along a gap of the
  /// loop bridged as a pole (contour/FaceLoops.cpp); NaN elsewhere.
  Vec3 at = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
};

/// Closed loops of boundary nodes in (u, v), the first node not repeated at the end.
/// Orientation is normalised: the face's region is on the LEFT of every loop in (u, v)
/// (outer loop counter-clockwise, holes clockwise), whatever the face's orientation in
/// 3D (the assembly flips triangles of reversed faces). On a seam the same global node
/// appears twice in the loops, at two different (u, v); at a pole (degenerate edge) several
/// consecutive boundary nodes share one global node.
struct FaceBoundary {
  int face = -1;  ///< 0-based model face
  std::vector<std::vector<BoundaryNode>> loops;
};

/// A face's triangulation in (u, v). Boundary vertices come first, in the order of the
/// FaceBoundary's loops (vertex k of the concatenated loops is uv[k]); interior vertices
/// follow with node[i] = −1 (the assembly creates their global nodes).
struct FaceMesh {
  std::vector<Vec2> uv;
  std::vector<int> node;
  std::vector<std::array<int, 3>> triangles;  ///< counter-clockwise in (u, v)
  /// Quadrilaterals after the quad conversion (--quad, mesher/quad/), counter-clockwise in
  /// (u, v); empty otherwise.
  std::vector<std::array<int, 4>> quads;
};

}  // namespace aniso
