#pragma once
// INTERIOR-CAVITY recovery (phase 2 of BoundaryRecovery.h; steps 2-3 in CavityRegion.h,
// step 4 in CavityStar.h) — what the thesis does with
// vicinity and boundary points (sec. 5.4.3–5.4.4), done without ever putting a point on
// the boundary:
//  1 the patch I: the set of missing boundary triangles connected to the missing entity
//    across MISSING edges (at most kMaxPatch), so that its rim edges are present; where the rim pinches at a vertex
//    (the two sides would touch there), I takes in every boundary triangle around its
//    vertices, present ones included;
//  2 the cavity C: every tet crossed by a triangle of I (around each mesh edge crossing
//    it) or by a missing edge inside I (beside each face it pierces, around each edge it
//    crosses) (Pipe.h), the tets on both sides of present triangles of I and around
//    present edges inside I;
//  3 the boundary faces of C split, across the rim edges, into an inner part (on the
//    material side of I) and an outer part; with I they close two polyhedra;
//  4 each polyhedron is retriangulated as the star of one point that sees all its faces
//    (a side without one grows, a few times, across the faces hiding a point of its
//    near-kernel: not across constrained faces, not around the rim)
//    (exact orient3d > 0 for every new tet): an existing vertex when one does (no new
//    point), else a new point — for the inner polyhedron strictly inside the solid, for
//    the outer one outside it;
//  5 the change is made only if the two stars have exactly C's boundary (RegionReplace.h),
//    their volume equals C's, and no boundary node would be left out; the triangles of I
//    are then faces of the mesh and are marked constrained.
// Anything that does not hold leaves the mesh untouched; then one point is inserted near
// the patch on the material side (insertVicinityPoint) for the next round to use. Within
// one round (newRound) a patch whose triangles all failed already is not retriangulated
// again: it only gets its vicinity point (each attempt puts it elsewhere), and the next
// round tries the stars with all of them.
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "mesher/volume/BoundaryTriangulation.h"
#include "mesher/volume/CavityRegion.h"
#include "mesher/volume/CavityStar.h"

namespace aniso::volume {

inline constexpr std::size_t kMaxPatch = 48;

class CavityRecovery {
 public:
  explicit CavityRecovery(BoundaryTriangulation& bt);

  /// Starts a round: every patch may be retriangulated once more.
  void newRound() { failedThisRound_.clear(); }

  /// Tries to recover boundary triangle f (and the missing triangles around it). Returns
  /// the number of new points (0, 1 or 2; 1 also when only a vicinity point went in).
  int recoverTriangle(int f);
  /// The same for boundary edge e, through the triangles that use it.
  int recoverEdge(int e);

  std::uint64_t attempts() const { return attempts_; }
  std::uint64_t successes() const { return successes_; }

 private:
  int recoverPatch(std::vector<int> seeds);
  /// Steps 2-5 for the patch: the number of new points, or a negative code (no change).
  int retriangulate(const std::vector<int>& patch);
  /// Step 5: the cavity replaced by the two stars if they have exactly its boundary and
  /// volume and leave no boundary node out; new apexes are added only then.
  int replaceByStars(const Cavity& cavity, const CavitySides& sides, const Apex& in, const Apex& out,
                     const std::vector<int>& patch);
  /// VICINITY (thesis 5.4.3) on the material side only: a point inserted (Delaunay, not
  /// across constrained faces) inside the solid near a patch no star recovers, so that
  /// the next round meets another configuration. Returns 1 when a point went in.
  int insertVicinityPoint(const std::vector<int>& patch);
  bool triangleMissing(int t);

  BoundaryTriangulation& bt_;
  std::unordered_map<std::uint64_t, std::vector<int>> edgeTriangles_;
  std::vector<std::vector<int>> vertexTriangles_;  ///< boundary triangles per kernel vertex
  std::vector<del3d::TetId> star_;
  std::unordered_map<int, int> vicinityAttempts_;  ///< per patch (its first triangle)
  std::unordered_set<int> failedThisRound_;        ///< triangles of the patches that failed this round
  std::uint64_t attempts_ = 0, successes_ = 0;
};

}  // namespace aniso::volume
