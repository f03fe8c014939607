#pragma once
// The seam — the topological correction of the conversion front at a small angle (thesis
// 4.7.3, alg. 4.5 step 3 "check seams", fig. 4.14; Owen's Q-Morph seam): where two
// adjacent front edges c→a and a→b enclose a region angle below seamAngle (metric) and the
// region there is the single triangle (a, b, c), the two front edges are closed into one:
// b and c become one vertex (at the boundary one of them if either is on the face
// boundary, else at their midpoint), the triangle and its neighbour across (b, c) vanish,
// and the quads on either side then share the edge from a. The region loses two triangles
// and the front cycle two edges, so the parity is kept.
// Check, then change: both may not be on the face boundary; the neighbour across (b, c)
// must be a live triangle; b and c may have no common neighbour other than a and that
// triangle's apex (the link condition); every element around the merged vertex must stay
// strictly convex and counter-clockwise, quads with scaled Jacobian ≥ min(minQuality,
// their value before). Otherwise nothing changes. The vertex given up is left without
// elements (QuadMesh2d::dropUnusedVertices removes it at the end).
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

struct SeamOptions {
  double seamAngle = 0.52359877559829887308;  ///< π/6
  double minQuality = 0.3;
};

struct SeamResult {
  bool done = false;
  int vertex = kNone;  ///< the merged vertex
  int element = kNone; ///< a live element at it
};

/// The corner of a seam: at the left (`left`: corner k) or right end of front edge k of
/// triangle e, the vertex a whose open region fan is that one triangle (a, b, c) under
/// `seamAngle` (metric); i is a's index in e, so a→b is edge i and c→a edge i + 2.
/// Shared by closeSeam and the transition seam (TransitionSeam.h).
struct SeamCorner {
  int a = kNone, b = kNone, c = kNone, i = kNone;
};
bool seamCorner(const QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, bool left, double seamAngle,
                SeamCorner& out);

/// Seam at the left (`left`: vertex a = corner k) or right end (vertex b) of front edge k
/// of triangle e, when its region angle is small enough and the checks pass.
SeamResult closeSeam(QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, bool left, const SeamOptions& options = {});

}  // namespace aniso::quad
