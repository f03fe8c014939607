#pragma once
// Recovery of the upper edge of a morphed quad (thesis 4.7.3, alg. 4.5 step 4, fig.
// 4.13(c)): the side vertices c and d must be joined by an edge. When they are not, the
// region's triangle edges crossed by the segment c→d (in (u, v), exact orient2d) are
// swapped, the first swappable one (union of its two triangles strictly convex) at a time,
// until the edge exists. Only live triangles of the region are touched: a crossing through
// a quad, the face boundary or a vertex lying on the segment ends the recovery unsuccessfully
// (the swaps made stay: each keeps the triangle mesh valid).
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

/// Whether some live element has c and d as neighbouring corners.
bool hasEdge(const QuadMesh2d& mesh, int c, int d, int hintAtC);

/// Recovers the edge (c, d); `hintAtC` is a live element with corner c. Returns whether the
/// edge exists at the end.
bool recoverTopEdge(QuadMesh2d& mesh, int c, int d, int hintAtC, int maxSwaps = 20);

/// A live element with corner v found from `hint` by the adjacency (hint itself when it has
/// v), or kNone.
int elementAt(const QuadMesh2d& mesh, int v, int hint);

}  // namespace aniso::quad
