#pragma once
// Diagonal collapse — a topological transformation of the quad mesh (thesis 4.8.1, fig.
// 4.17: removing an unnecessary element). A quad (v0, v1, v2, v3) whose opposite corners
// v0 and v2 are inner vertices with three elements each (valence 3, against the ideal 4)
// is removed by merging v0 and v2 into one vertex at their midpoint: the merged vertex has
// valence 4, and v1 and v3 lose one element each, so it is done only when both keep
// enough (an inner one at least 4, a boundary one at least 2). The worst shape of such a
// 3-3 quad (two corners near 120°) goes with it.
// Check, then change: v0 and v2 share no neighbour but v1 and v3 and no element but the
// quad (the link condition); every element around the merged vertex strictly convex and
// counter-clockwise, quads with scaled Jacobian ≥ min(minQuality, the worst of them
// before). Otherwise nothing changes. v2 is left without elements
// (QuadMesh2d::dropUnusedVertices removes it at the end).
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

/// One pass over the quads (in id order, each vertex changed at most once); returns the
/// number of quads collapsed.
int collapseDiagonals(QuadMesh2d& mesh, VertexMetrics& metrics, double minQuality);

}  // namespace aniso::quad
