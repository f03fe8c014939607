#pragma once
// Relocation of one free vertex of a SolidTetMesh (sec. 5.6.1 and sliver removal).
// Check, then change: a position is legal when every tet of the vertex's star stays
// positively oriented (exact orient3d with the vertex at the new position); fixed vertices
// (node ≥ 0) are never moved.
//
// smooth(): Laplace smoothing, the target being the mean of the star's other vertices
//   (eq. 4.2), or where the local gradation (the largest relative Frobenius difference
//   between the vertex's tensor and a neighbour's) exceeds lowGradation, the metric
//   version (eq. 4.3, with the mean instead of the sum and each mid-edge tensor scaled to
//   the determinant of the vertex's, as mesher/surface/improve/LaplaceSmoothing.h).
//   Accepted when legal and the star gets better in η_M: a poor star (worst below
//   qualityFloor) raises its worst, another keeps the worst ≥ qualityFloor and does not
//   lower its mean of η_M³ (the cube: no cube roots, and the poorer tets weigh less than
//   in the plain mean, for the same mean ratio: docs/measurements.md); else the
//   half move is tried. Stars are compared on η_M³ throughout (VertexMetrics::score).
//   With `ascent`, a step of steepest ascent of the star's mean η_M (analytic gradient,
//   backtracking line search: ascentStep) is tried first, under the same acceptance: the
//   Laplace target ignores the tets' shapes (its gain and cost: docs/volume.md).
// relocate(): for slivers: the Laplace target, the position making the star's worst tet
//   regular (the apex over its opposite face, in its metric) and the midpoint towards it,
//   and deterministic perturbations (26 directions of the cube around the vertex, two radii
//   relative to the shortest edge of the star); the legal candidate with the largest worst
//   η_M of the star wins if it beats the current worst. In the angles mode a compass
//   search then continues from the best position (VertexMover.cpp: kAngleSearchSteps).
#include <vector>

#include "mesher/volume/SolidTetMesh.h"
#include "mesher/volume/improve/TetScores.h"
#include "mesher/volume/improve/VertexMetrics.h"
#include "mesher/volume/improve/VertexTets.h"

namespace aniso::improve3d {

/// ascentStep(): first line-search step, relative to the mean distance from the vertex to
/// its neighbours, and the halvings after it.
inline constexpr double kAscentFirstStep = 0.2;
inline constexpr int kAscentHalvings = 7;

class VertexMover {
 public:
  VertexMover(SolidTetMesh& s, VertexMetrics& vm) : s_(s), vm_(vm) {}

  /// With a score cache (setScores) the star's current scores are read from it and the
  /// cache is kept exact on every accepted move (TetScores' contract).
  bool smooth(del3d::VertexId v, double lowGradation, double qualityFloor, bool ascent = false);
  /// The cache smooth() reads and updates (nullptr: none). relocate() must not be used
  /// while one is set (it leaves the cache stale).
  void setScores(TetScores* scores) { scores_ = scores; }
  /// Stars read from this incidence instead of walked (nullptr: walked); it must stay
  /// valid (no topology change) while set.
  void setIncidence(const VertexTets* incidence) { incidence_ = incidence; }
  /// angles: maximise the star's smallest min(θ_min, 180° − θ_max) (dihedral angles in
  /// each tet's metric) instead of its worst η_M, keeping the worst η_M³ above half its
  /// value.
  bool relocate(del3d::VertexId v, bool angles = false);

 private:
  void loadStar(del3d::VertexId v);
  /// Every star tet positive with v at p; right after quality(v, p) (`trialScored`) the
  /// trial scores that certify the orientation (VertexMetrics::certifiesOrientation) stand
  /// for orient3d.
  bool legal(del3d::VertexId v, const Vec3& p, bool trialScored) const;
  /// Worst and mean score of the star with v at p; the per-tet scores are left in trial_.
  /// Returns false (worst, mean and trial_ incomplete) as soon as a tet scores below
  /// rejectBelow.
  bool quality(del3d::VertexId v, const Vec3& p, double& worst, double& mean, double rejectBelow = -1e300);
  Vec3 laplaceTarget(del3d::VertexId v, double lowGradation) const;
  /// Mean η_M of the loaded star with v at p; −1 when a tet is inverted or flat there.
  double meanEta(del3d::VertexId v, const Vec3& p) const;
  /// One line-searched step of steepest ascent of meanEta from v's position; that position
  /// when no step improves it.
  Vec3 ascentStep(del3d::VertexId v) const;
  Vec3 worstApex(del3d::VertexId v) const;
  /// The star's smallest min(θ_min, 180° − θ_max) with v at p; stops (returning a value at
  /// or below it) once it is at or below stopAtOrBelow.
  double angleMeasure(del3d::VertexId v, const Vec3& p, double stopAtOrBelow) const;
  void move(del3d::VertexId v, const Vec3& p);

  SolidTetMesh& s_;
  VertexMetrics& vm_;
  TetScores* scores_ = nullptr;
  const VertexTets* incidence_ = nullptr;
  std::vector<del3d::TetId> star_;
  std::vector<double> trial_;  ///< per star tet: the score of the last quality() call
  std::vector<std::uint32_t> order_;   ///< relocate(): the star sorted by score
  std::vector<del3d::TetId> sorted_;
  std::vector<std::uint32_t> nbrs_;  ///< the star's other vertices, in discovery order
  std::vector<std::uint32_t> seen_;  ///< per vertex: stamp_ when already in nbrs_
  std::uint32_t stamp_ = 0;
};

}  // namespace aniso::improve3d
