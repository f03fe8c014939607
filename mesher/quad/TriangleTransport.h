#pragma once
// Pairing of the triangles left by the conversion (thesis 4.7: an all-quad mesh wherever
// the boundary counts are even). A face whose boundary loops are all even has an even
// number of triangles in every edge-connected part (3T + 4Q = 2E_i + E_b), so the
// triangles left over can be paired up: for each one, the nearest other triangle is found
// by a breadth-first search through the elements, and the triangle is moved along that
// path — at each quad on the way, the pentagon (triangle ∪ quad) is cut into a quad and a
// triangle that holds the pentagon edge leading to the next element (two such cuts, the
// better one in metric is taken) — until it meets its partner, with which it is merged.
// Check, then change: every cut and the final merge must give strictly convex,
// counter-clockwise elements with quads of metric scaled Jacobian ≥ minQuality; when a path
// cannot be completed its moves are undone and the next nearest triangle is tried.
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

struct TransportOptions {
  double minQuality = 0.1;
  int maxPathLength = 64;  ///< elements
  int partners = 6;        ///< nearest triangles tried, in turn, for each triangle
  int rounds = 4;
};

struct TransportStats {
  int paired = 0;   ///< pairs merged into quads
  int moves = 0;    ///< pentagon cuts
  int triangles = 0;  ///< live triangles left
};

TransportStats pairTriangles(QuadMesh2d& mesh, VertexMetrics& metrics, const TransportOptions& options = {});

}  // namespace aniso::quad
