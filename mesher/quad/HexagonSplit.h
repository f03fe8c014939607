#pragma once
// The second last resort for two adjacent triangles (after PairSplit.h): the pair and a
// quad next to it. When the pair's union cannot be cut into quads by itself — its outline
// has a flat corner (a straight-boundary vertex, ≈ 180°) or a sharp one that the five-quad
// split would halve — the union of the pair (4 corners) and a quad q on one of its four
// outer edges is a hexagon h0..h5, and a hexagon is covered by four quads with two new
// inner vertices X1, X2 on a central edge:
//   (h2, h3, h4, X1), (h5, h0, h1, X2), (h4, h5, X2, X1), (h1, h2, X1, X2)
// for each of the three rotations of the labels. So the flat boundary vertex becomes the
// corner of a quad together with the boundary vertex next to it, and a sharp boundary
// corner the corner of a single quad (a parallelogram there when the angle allows it).
// Candidate positions: X1 on the ray from h3 through the midpoint m of h2 and h4, at
// m + τ (m − h3) (τ = 0.1 … 1, 1 the parallelogram completion), moved 0, 0.3 or 0.6 of the
// way to the hexagon's vertex centroid; X2 alike from h0. Check, then change: the best candidate (largest worst quad, then lowest
// rotation/candidate index) is taken when all four quads are strictly convex,
// counter-clockwise and of scaled Jacobian ≥ minQuality (QuadShape.h elementQuality);
// the outline is unchanged, so nothing outside changes. Otherwise the mesh is untouched.
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

/// Triangles a and b must share an edge. Returns whether the pair and one quad next to it
/// were replaced by four quads (the quads next to the pair are tried in the order of the
/// pair's outer edges).
bool splitPairWithQuad(QuadMesh2d& mesh, VertexMetrics& metrics, int a, int b, double minQuality);

}  // namespace aniso::quad
