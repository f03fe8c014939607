#pragma once
// Re-triangulation of a folded region of one face (the second step of UnfoldSurface.h,
// for folds that no single flip mends — e.g. a face node folded over a run of nearly
// collinear rim nodes, or a strip of rim slivers):
//  1 the region R: for a seed pair (two triangles on a folded edge), the triangles turned
//    away from one of them (kFoldCosine against its normal) reached from the other across
//    the face's edges, plus that one — a pocket of rim slivers with the triangle across
//    its chord; else every triangle of the face incident to a vertex of the seeds, grown
//    by one ring (at most kMaxRings times) until step 2 holds;
//  2 the boundary of R as a chain (directed edges that do not cancel) is one simple loop,
//    and R is nearly flat (every node of R within kMaxLoopBend of the loop's extent from
//    the plane of the loop's vector area; kMaxHubBend around a hub, below), so the
//    surface is not reshaped;
//  3 the nodes inside the loop are used by R only (no other face uses them) and are face
//    nodes, dropped from the triangulation (they stay in the node array, in no element),
//    but for at most one CAD vertex or edge node, the hub, which is kept;
//  4 the loop, projected on that plane, is triangulated by ear clipping (exact orient2d,
//    the best-shaped ear first), or with a hub as the fan from it (every loop edge must
//    see it on its inner side: problemSphere's pole vertex, whose three triangles lay one
//    turned over, beyond a neighbour's edge); every new triangle must be positive there
//    and must not repeat a triangle of the mesh.
// Returns false (nothing changed) when a step fails. `tris` are the face's triangles,
// `useCount` the number of mesh triangles using each node, `existing` the sorted node
// triples of every mesh triangle.
#include <array>
#include <set>
#include <vector>

#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

/// Two triangles of one face sharing an edge are folded when the cosine of the angle
/// between their normals is below this (about 84 degrees; within the curvature ratio
/// adjacent triangles of a smooth face differ by far less, and a sliver across its face —
/// three nearly collinear rim nodes — stands at about 90 degrees to its neighbours).
inline constexpr double kFoldCosine = 0.1;

struct FoldRepair {
  std::vector<int> removed;                   ///< indices into the face's triangles
  std::vector<std::array<int, 3>> added;      ///< the new triangles, the face's orientation
  int nodesDropped = 0;
};

bool retriangulateFold(const SurfaceMesh& mesh, const std::vector<std::array<int, 3>>& tris,
                       const std::vector<int>& seed, const std::vector<int>& useCount,
                       const std::set<std::array<int, 3>>& existing, FoldRepair& out);

}  // namespace aniso
