#pragma once
// improveVolume — improvement of the tetrahedral mesh of one solid (thesis sec. 5.6,
// alg. 5.4), then sliver removal (issue 5):
//   for i = 1..passes (table 5.6: one pass by default, later passes degrade graded and
//   anisotropic meshes), and further passes up to maxPasses while the mean η_M of the solid
//   is below passTarget (graded parts gain from a second and a third pass, the degradation
//   of table 5.6 being μ_M's and small; a uniform mesh above the target stops at one; beyond
//   five passes the gain is small for the time: docs/measurements.md):
//     smoothing of the free vertices (sec. 5.6.1): a step of steepest ascent of the star's
//       mean η_M (VertexMover::smooth), else Laplace: the mean of the neighbours, or
//       the metric version (eq. 4.3) where the local gradation is high; a move is kept
//       only when every tet of the star stays positive (exact orient3d) and the star's
//       worst η_M does not decrease (else the half move is tried);
//     geometric flipping (sec. 5.6.2): T23 for faces, T32 / T44 for edges (legality by
//       the kernel's exact checks; constrained faces are never removed) whenever the
//       worst η_M of the new tets beats that of the old ones by flipGain; the tets with
//       η_M below flipCandidate are visited (the thesis visits all), a changed region is
//       revisited;
//     vertex removal (improve/VertexRemoval.h): a free vertex whose star is poor is removed
//       when a retriangulation of its star (edge collapse, or the Delaunay triangulation of
//       its link) raises the star's worst η_M — the topological step that undoes crowded
//       refinement points, where a solid is one or two elements across; the flips then
//       visit the new tets.
//   sliver removal: every tet whose smallest dihedral angle is below sliverAngleDeg (in
//     its metric), or with a Euclidean dihedral angle outside [euclideanSliverAngleDeg,
//     180° − euclideanSliverAngleDeg], is attacked (improve/SliverRemoval.h) by (1) flips
//     of its faces and edges, (2) relocation of its free vertices (smoothing target, then
//     deterministic perturbations), (3) a point inserted at its metric circumcentre
//     (del3d::Inserter, mustRemove = the sliver) followed by (2) on the new vertex — each
//     accepted when it raises the local minimum of min(η_M, η) (the metric and the
//     Euclidean mean ratio); rounds repeat while they make progress (at most sliverRounds).
// η_M of a tet uses the mean of the four vertices' transformation tensors (cached per
// vertex, one control-space call per vertex: improve/VertexMetrics.h).
// Cost (the same decisions, measured once): each tet's score is computed once per pass and
// kept exact by the smoothing and the flips (improve/TetScores.h), the stars of the
// smoothing are read from one incidence snapshot (improve/VertexTets.h), a trial position
// is dropped at its first tet that already rejects it, a trial's Euclidean score certifies
// the orientation (orient3d only below kOrientationCertificate), run() of the flips skips
// faces and edges already tried on the same tets, and the sliver test asks the mean ratio
// bound η³ ≤ 2 sin²θ before the dihedral cosines (docs/measurements.md). Fixed vertices
// (node ≥ 0) never move; the hull (the constrained boundary triangles) is unchanged, so
// validateSolidTetMesh holds afterwards.
// Deterministic.
#include <cstddef>

#include "mesher/core/Cancel.h"
#include "mesher/control/ControlSpace3d.h"
#include "mesher/volume/SolidTetMesh.h"
#include "mesher/volume/improve/VertexMetrics.h"
#include "mesher/volume/improve/VertexRemoval.h"

namespace aniso {

struct VolumeImproveOptions {
  int passes = 1;              ///< N_imp of alg. 5.4 (table 5.6): passes always made
  /// Further passes, up to maxPasses, while the solid's mean η_M after a pass is below
  /// passTarget (see above).
  int maxPasses = 5;
  double passTarget = 0.85;
  int smoothingSweeps = 1;     ///< Laplace sweeps per pass
  /// Each smoothing move tries a step of steepest ascent of the star's mean η_M first
  /// (VertexMover::smooth).
  bool ascentSmoothing = true;
  double lowGradation = 0.05;  ///< δ_M threshold of the mixed (plain / metric) smoothing
  double flipGain = 1e-3;      ///< required increase of the worst η_M for a flip
  /// Tets visited by the flip pass: η_M below this (> 1: all tets, as the thesis). 0.7: a
  /// better mean ratio than visiting all tets, in less than half the time
  /// (docs/measurements.md).
  double flipCandidate = 0.7;
  /// Sliver removal target (smallest dihedral angle in the metric). 15°: a smallest angle
  /// above Gmsh HXT's, for the time 10° takes (docs/measurements.md).
  double sliverAngleDeg = 15.0;
  /// Also a sliver: a Euclidean dihedral angle below this or above 180° minus this (the
  /// referee's measure; matters for anisotropic meshes).
  double euclideanSliverAngleDeg = 5.0;
  int sliverRounds = 4;
  /// Removal of crowded free vertices after the flips of each pass (improve/VertexRemoval.h;
  /// the created tets are offered to the flips).
  bool vertexRemoval = true;
  improve3d::VertexRemovalOptions removal;
  bool sliverInsertion = true;  ///< allow step (3)
  /// Checked before every pass and operator sweep (Cancel.h); null: never stops.
  const CancelToken* cancel = nullptr;
  /// Threads of the smoothing (classes of independent vertices, SmoothingSchedule.h): the
  /// same mesh for any number.
  int threads = 1;
};

struct VolumeImproveStats {
  int passes = 0;         ///< passes made
  std::size_t moved = 0;  ///< accepted smoothing moves
  std::size_t flips23 = 0, flips32 = 0, flips44 = 0;
  std::size_t removed = 0;  ///< free vertices removed (VertexRemoval)
  std::size_t sliversBefore = 0;  ///< tets below sliverAngleDeg before sliver removal
  std::size_t sliversAfter = 0;
  std::size_t sliverFlips = 0, sliverMoves = 0, sliverInsertions = 0, sliverEdgeRemovals = 0,
              sliverSteinerPoints = 0, sliverReconnections = 0;
  int sliverMetricRounds = 0;  ///< sliver rounds run in the metric (none in a film)
  double smoothingSeconds = 0, flipSeconds = 0, removalSeconds = 0, sliverSeconds = 0;  ///< wall time of the steps
};

/// `metrics` (optional): the per-vertex tensors to use, built on s.mesh and cs by the caller;
/// afterwards they are current for every vertex (moved ones re-queried, new ones added), so
/// that the quality report can read them (accumulateTetQuality) instead of querying again.
VolumeImproveStats improveVolume(SolidTetMesh& s, const ControlSpace3d& cs, const VolumeImproveOptions& o = {},
                                 improve3d::VertexMetrics* metrics = nullptr);

}  // namespace aniso
