#pragma once
// Sliver removal by a Steiner point inside the solid (issue 5 §1, "inserting an interior
// point"), for slivers the flips, edge removal and vertex moves cannot remove and the
// Delaunay insertion (SliverRemoval.h step 3) refuses — typically a sliver whose four
// vertices are surface nodes, with one or two faces on the boundary, at a nearly flat
// fold across a CAD edge or next to a small CAD feature, smaller than the local size.
//
// A region R around the sliver t is replaced by the star of a new free vertex p: one tet
// per boundary face of R (p put in place of the vertex opposite that face), at most
// del3d::kMaxLocalTets of them. The regions tried: (a) t and every subset of at most
// kMaxRegionNeighbours of its neighbours across its interior faces, smallest first;
// (b) the closed ring of each interior edge of t (p splits the edge: a flat cap over two
// nearly coplanar boundary faces becomes two tets on those faces with p as apex).
// Check, then change: every new tet positively oriented (exact orient3d on the
// coordinates), every vertex of R still in a new tet (no vertex disappears), and the worst
// score of the new tets (VertexMetrics: the mean of the vertices' tensors, p taking the
// mean tensor of t) better than the worst of R. Candidates for p: the centroids of t and
// of R and their midpoint; for each boundary face of t (on the hull of the solid) the apex
// of a tet on it at heights kApexHeights of its mean edge length, towards the inside; for
// (b) the edge's midpoint and the points a quarter and half way from it to the centroid of
// the ring's other vertices. The best candidate over all regions wins. The hull and the
// constrained faces are unchanged (validateSolidTetMesh
// holds); deterministic (fixed orders, no randomness).
#include <vector>

#include "mesher/volume/SolidTetMesh.h"
#include "mesher/volume/improve/VertexMetrics.h"

namespace aniso::improve3d {

/// At most this many neighbours of the sliver join the region.
inline constexpr int kMaxRegionNeighbours = 3;
/// Heights of the apex candidates over a boundary face, relative to its mean edge length
/// (sqrt(2/3) ≈ 0.816: the regular tet).
inline constexpr double kApexHeights[3] = {0.816, 0.5, 0.25};

/// Replaces the live tet t and some neighbours by the star of a new free vertex when that
/// beats their worst score; then syncs vm, appends the new tets to `created`, and returns
/// the new vertex (invalid when nothing changed).
del3d::VertexId insertSteinerPointAtSliver(SolidTetMesh& s, VertexMetrics& vm, del3d::TetId t,
                                           std::vector<del3d::TetId>& created);

}  // namespace aniso::improve3d
