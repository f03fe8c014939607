#pragma once
// Sliver removal (issue 5 §1, after alg. 5.4): a tet is a sliver when its smallest
// dihedral angle, measured in its metric (VertexMetrics::isSliver; Euclidean for
// an isotropic field), is below the target angle, or when a Euclidean dihedral angle is
// below the Euclidean target or above 180° minus it (the referee measures in space: an
// anisotropic metric may find a flat tet acceptable). The operators below maximise the
// smaller of the metric and the Euclidean mean ratio (VertexMetrics::setGuardEuclidean).
// Each round visits the slivers in slot order and, for each one still a sliver, tries in
// turn:
//   1 flips of its faces and edges (QualityFlips::visit with gain 0, repeated on the
//     tets created while one of them is still a sliver);
//   1b removal of one of its edges with a ring of up to volume::kMaxRemovalRing tets
//     (QualityEdgeRemoval.h: the best fan of the ring polygon), then flips as in 1;
//   2 relocation of its free vertices (VertexMover::relocate);

//   3 (optional) a point at its metric circumcentre or, failing that, at the apex of the
//     regular tet (in its metric) on one of its boundary faces — a sliver lying on a
//     curved boundary (two boundary faces, four surface nodes) has its circumcentre far
//     away — inserted with del3d::Inserter (transform = the metric there, mustRemove =
//     the sliver, never crossing a constrained face; cancelled when outside the solid or
//     closer than kSliverInsertDistance times min(1, the sliver's mean edge length), in
//     that metric, to a vertex of its containing tet: a sliver much smaller than the local
//     size takes a point at its own scale), then relocation of the new vertex and flips of its star.
//   4 (optional, when 3 inserts nothing) the sliver and some of its neighbours replaced by
//     the star of a new free vertex (SliverSteinerPoint.h), relocated, then flips of its
//     star.
//   5 (when 3 and 4 insert nothing or are left out) a sliver with a Euclidean dihedral
//     angle below kReconnectionAngleDeg: it and the tets around it tetrahedralized again
//     with the same vertices and boundary (PolyhedronReconnection.h: a search, too dear for
//     every tet of a film below the target), again on a tet it made still below that
//     angle (kReconnectionChain), then flips as in 1. Tried before 3 and 4 it
//     changed what they found later, for the worse (docs/measurements.md).
// A solid where more than kFilmSliverShare of the tets are slivers is thinner than its
// elements (a film or label the proximity rounds could not refine): steps 3 and 4 are left
// out, where every new point only adds flat tets, and so are the rounds in the metric,
// whose flips and moves only shuffle flat tets there (measured: docs/volume.md).
// Every round visits every sliver of the mesh (in slot order; the operators make new tets,
// some of them slivers); rounds stop when one does not lower the number of slivers or
// after `rounds` (a round may also leave more slivers than it found: docs/volume.md).
// Then the same rounds over the Euclidean slivers alone (the referee's: the operators on
// the others leave a few behind after their slots were visited).
#include <cstddef>
#include <vector>

#include "mesher/control/ControlSpace3d.h"
#include "mesher/volume/SolidTetMesh.h"
#include "mesher/volume/improve/TetScores.h"
#include "mesher/volume/improve/VertexMetrics.h"

namespace aniso::improve3d {

/// Metric distance below which a sliver's circumcentre is too close to an existing vertex
/// (times min(1, the sliver's mean metric edge length)).
inline constexpr double kSliverInsertDistance = 0.25;
/// Step 5 only for slivers flatter than this (degrees, Euclidean): the referee's bar.
inline constexpr double kReconnectionAngleDeg = 2.0;
/// Step 5 goes on with a flat tet it made, at most this many reconnections in a row.
inline constexpr int kReconnectionChain = 4;
/// Above this share of slivers among a solid's tets, the solid is a film: no points are
/// inserted (steps 3, 4) and no rounds run in the metric (header).
inline constexpr double kFilmSliverShare = 0.3;

struct SliverStats {
  std::size_t before = 0, after = 0;
  std::size_t flips = 0, moves = 0, insertions = 0;
  std::size_t edgeRemovals = 0, steinerPoints = 0, reconnections = 0;
  int metricRounds = 0;  ///< rounds run in the metric (none in a film)
  /// Adds o's operation counts (not before / after).
  void merge(const SliverStats& o) {
    flips += o.flips, moves += o.moves, insertions += o.insertions;
    edgeRemovals += o.edgeRemovals, steinerPoints += o.steinerPoints, reconnections += o.reconnections;
  }
};

/// The live slivers of s in slot order (VertexMetrics::isSliver). With `scores` (exact for
/// the mesh as it is, TetScores.h) an isotropic tet whose cached η³ excludes the angles
/// (SliverAngles) is passed over without being measured again.
std::vector<del3d::TetId> liveSlivers(const SolidTetMesh& s, const VertexMetrics& vm, double angleDeg,
                                      double euclideanDeg, const TetScores* scores = nullptr);

/// Number of live slivers of s (VertexMetrics::isSliver).
std::size_t countSlivers(const SolidTetMesh& s, const VertexMetrics& vm, double angleDeg, double euclideanDeg);

/// `scores`: optional, exact at the call (the smoothing and flips' cache); read by the first
/// scan only (the operators here do not keep it).
SliverStats removeSlivers(SolidTetMesh& s, const ControlSpace3d& cs, VertexMetrics& vm, double angleDeg,
                          double euclideanDeg, int rounds, bool insertion, const TetScores* scores = nullptr);

}  // namespace aniso::improve3d
