#pragma once
// The last resort for two adjacent triangles that cannot be merged into a good quad (the
// union is not convex, or its scaled Jacobian is too low): their union, a quadrilateral
// region P0..P3 (star-shaped from the midpoint C of the shared edge), is split into five
// quads — an inner quad G0..G3, G_i on the ray from C to P_i at the metric distance
// λ min_j |C P_j| (a kite even when the region has a reflex corner), and the four quads
// (P_i, P_i+1, G_i+1, G_i) around it. Only new inner vertices are added: the region's
// outline is unchanged, so nothing outside changes. λ = 0.5, 0.35, 0.7 are tried; the first
// whose five quads are strictly convex, counter-clockwise and of scaled Jacobian ≥
// minQuality (QuadShape.h elementQuality) is taken, else nothing changes.
#include <array>

#include "mesher/quad/QuadShape.h"

#include <optional>

namespace aniso::quad {

/// The outline of two adjacent live triangles a and b: corners p0..p3 counter-clockwise
/// (p0, p2 the ends of the shared edge, p1 b's apex, p3 a's apex) and the element outside
/// each outline edge (p_j, p_j+1) (kNone on the face boundary). Empty when a and b are not
/// two live triangles sharing an edge.
struct PairOutline {
  std::array<int, 4> p;
  std::array<int, 4> outside;
};
std::optional<PairOutline> pairOutline(const QuadMesh2d& mesh, int a, int b);

/// Triangles a and b must share an edge. Returns whether the split was made.
bool splitPairIntoQuads(QuadMesh2d& mesh, VertexMetrics& metrics, int a, int b, double minQuality);

}  // namespace aniso::quad
