#pragma once
// Edge removal by quality (thesis sec. 5.2.2 "extended to cases with more than three
// tetrahedra incident to an edge", used as an improvement operator of sec. 5.6.2 and by
// sliver removal, issue 5 §1): the n tets around an interior edge (closed ring of
// 3..volume::kMaxRemovalRing tets, no constrained face around it) are replaced by the
// 2(n-2) tets joining the edge's ends to a fan triangulation of the ring polygon
// (volume/EdgeRemoval.h: every triangulation of rings up to 5). Of the legal fans (exact
// orient3d), the one whose worst VertexMetrics::score is largest is applied when it beats
// the ring's worst score. A sliver whose four vertices lie on the boundary (two boundary
// faces at a nearly flat fold across a CAD edge) is removed this way when the ring of its
// interior edge is larger than the flips T32/T44 handle. Check, then change; the hull and
// the constrained faces are unchanged (validateSolidTetMesh holds). Deterministic.
#include <vector>

#include "mesher/volume/SolidTetMesh.h"
#include "mesher/volume/improve/VertexMetrics.h"

namespace aniso::improve3d {

/// Removes the edge joining local vertices i and j of the live tet t when a fan beats the
/// ring's worst score; appends the new tets to `created` and returns true (t is then dead).
bool removeEdgeByQuality(SolidTetMesh& s, const VertexMetrics& vm, del3d::TetId t, int i, int j,
                         std::vector<del3d::TetId>& created);

}  // namespace aniso::improve3d
