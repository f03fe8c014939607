#pragma once
// TriangleFlip — the edge swap of two triangles of a quad-conversion mesh, shared by the
// morphing operators (side-edge selection, SideEdge.h; upper-edge recovery,
// TopEdgeRecovery.h): edge k (corners k, k+1 = x, y) of triangle f = (x, y, p), shared
// with triangle g = (y, x, w), becomes (p, w): (p, x, w) + (p, w, y), made only when both
// are strictly convex and counter-clockwise (QuadShape.h convexCCW).
#include "mesher/quad/QuadMesh2d.h"

namespace aniso::quad {

/// Swaps edge k of triangle f. Returns w (the neighbour's corner opposite the edge), or
/// kNone when f's neighbour across k is no triangle or the swap would not be legal.
int flipTriangleEdge(QuadMesh2d& mesh, int f, int k);

}  // namespace aniso::quad
