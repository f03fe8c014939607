#pragma once
// Per-vertex metric cache of the improvement phase (sec. 5.6): one control-space call per
// vertex; the metric of a tetrahedron is the mean of its four vertices' transformation
// tensors (a mean of SPD matrices is SPD; for a constant field it is that field). η_M of
// a tet (MeanRatio.h) is measured in that mean, so comparing configurations of the same
// vertices (flips, relocations) costs no control-space call. When the four tensors are
// isotropic (s·I, up to kIsotropicTolerance) the mean is too and η_M = η: no transform.
// score() is the signed η_M³: the same order as η_M without the cube root (for minima).
// With setGuardEuclidean(true) (sliver removal) score(), scoreWith() and scorePoints() return
// the smallest of the metric value, the Euclidean value and the cubed Euclidean dihedral
// sine (min_e sin θ_e / sin 70.53°)³: a tet that is fine in the metric but flat in space
// (what the referee measures) counts as poor, and of two poor tets the one with the smaller
// dihedral angle is the worse — a spire (three vertices close together, every dihedral
// angle large) has a mean ratio as low as a sliver's, and maximising the mean ratio alone
// traded such tets for slivers at a short boundary feature (docs/measurements.md).
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "mesher/control/ControlSpace3d.h"
#include "mesher/delaunay3d/TetMesh.h"
#include "mesher/volume/refine/VertexTensors.h"
#include "mesher/metric/IsotropicTensor.h"

namespace aniso::improve3d {

/// sin of the regular tet's dihedral angle acos(1/3).
inline constexpr double kRegularDihedralSine = 0.9428090415820634;

/// A Euclidean score above this certifies the tet's positive orientation (the filter stage
/// of orient3d, VertexMetrics::certifiesOrientation). Error analysis: the score is
/// s = 432 D² / Σ³ · sign(D), D = (p2−p1)·((p3−p1)×(p4−p1)) evaluated in floating point from
/// the coordinates, Σ the sum of the six squared edge lengths. Shewchuk's bound for that
/// evaluation is |D̃ − D| ≤ (7 + 56ε) ε · permanent ≤ 1.6e−15 · S^{3/2} with S the sum of
/// the three squared edge vectors (permanent ≤ ‖a‖₁‖b‖₁‖c‖₁ ≤ S^{3/2}), and S ≤ Σ; so
/// s > 1.1e−27 (with rounding of s itself) implies D̃ > |D̃ − D|, D > 0. 1e−12 (η > 1e−4)
/// leaves a margin of 15 orders of magnitude; tets below it take the exact predicate.
inline constexpr double kOrientationCertificate = 1e-12;

class VertexMetrics {
 public:
  VertexMetrics(const del3d::TetMesh& mesh, const ControlSpace3d& cs) : mesh_(mesh), cs_(cs) { sync(); }
  /// With the tensors the refinement queried from the same control space at the same
  /// (unmoved) vertices: taken instead of querying them again; the vertices beyond the
  /// table are queried.
  VertexMetrics(const del3d::TetMesh& mesh, const ControlSpace3d& cs, const refine3d::VertexTensorTable& seed)
      : mesh_(mesh), cs_(cs) {
    sync(&seed);
  }
  /// Queries the metric of vertices added to the mesh since the last call.
  void sync(const refine3d::VertexTensorTable* seed = nullptr);
  const Mat3& at(del3d::VertexId v) const { return m_[v.index]; }
  /// Re-queries v's metric (after v moved).
  void refresh(del3d::VertexId v);

  Mat3 tetMetric(const std::uint32_t* v) const { return 0.25 * (m_[v[0]] + m_[v[1]] + m_[v[2]] + m_[v[3]]); }
  /// Signed η_M³ of the tet with vertex ids v (monotone in η_M).
  double score(const std::uint32_t* v) const;
  double score(const std::array<del3d::VertexId, 4>& v) const {
    const std::uint32_t ids[4] = {v[0].index, v[1].index, v[2].index, v[3].index};
    return score(ids);
  }
  double score(del3d::TetId t) const { return score(mesh_.tetVertices(t)); }
  /// η_M of the tet with vertex ids v (signed).
  double eta(const std::uint32_t* v) const { return std::cbrt(score(v)); }
  /// score() of the tet with vertex ids v where vertex `moved` is placed at p.
  double scoreWith(const std::uint32_t* v, std::uint32_t moved, const Vec3& p) const;
  /// η_M (unguarded: the tet's metric only) of the tet with vertex ids v, and its gradient
  /// with respect to the position of vertex `moved` (one of v), at the current positions.
  /// From η = 432^{1/3} D'^{2/3} / Σ' in the tet's metric x' = T x (D' = det T · D, D six
  /// times the signed volume; Σ' the squared edge lengths under TᵀT): ∇η = η (2/3 ∇D / D −
  /// ∇Σ' / Σ'). 0 and a zero gradient for a tet not positively oriented.
  double etaGradient(const std::uint32_t* v, std::uint32_t moved, Vec3& gradient) const;
  /// score() of the points p[0..3] (not necessarily vertices) measured in the tensor m;
  /// Euclidean only when `isotropicTensor`.
  double scorePoints(const Vec3* p, const Mat3& m, bool isotropicTensor) const;
  bool isIsotropic(del3d::VertexId v) const { return iso_[v.index] != 0; }
  /// True when `score`, computed by score()/scoreWith() for the tet with vertex ids v (in
  /// the current guard mode), certifies that the tet is positively oriented in space: it is
  /// (or bounds from above) the Euclidean score — the guard is on or the tet is
  /// isotropic — and exceeds kOrientationCertificate. False: decide with orient3d.
  bool certifiesOrientation(const std::uint32_t* v, double score) const {
    return score > kOrientationCertificate && (guardEuclidean_ || isotropic(v));
  }
  /// The tet with vertex ids v is measured in Euclidean space (its four tensors isotropic).
  bool isIsotropic(const std::uint32_t* v) const { return isotropic(v); }
  /// A sliver: metric smallest dihedral below metricAngle, or a Euclidean dihedral angle
  /// below euclideanAngle or above 180° − euclideanAngle (degrees).
  bool isSliver(del3d::TetId t, double metricAngle, double euclideanAngle) const {
    return isSliver(t, SliverAngles(metricAngle, euclideanAngle));
  }
  /// The sliver thresholds as cosines (isSliver compares the dihedral angles' cosines:
  /// dihedralCosineOutside of TetQuality.h, no acos), and as mean ratios that exclude them:
  /// every dihedral angle θ of a tet satisfies η³ ≤ 2 sin²θ (with L the length of θ's edge
  /// and d_1, d_2 the distances of the two other vertices to its line, V = L d_1 d_2 sin θ
  /// / 6 and Σ l² ≥ 2 (L² + d_1² + d_2²); then AM-GM), so η³ > 2 sin²θ_0 puts every angle in
  /// (θ_0, 180° − θ_0): isSliver tests the (cheaper) mean ratio first.
  struct SliverAngles {
    SliverAngles(double metricAngle, double euclideanAngle);
    double cosMetric, cosEuclidean, cosIsotropic;  ///< cos θ_M, cos θ_E, cos max(θ_M, θ_E)
    double etaMetric, etaEuclidean, etaIsotropic;  ///< the η³ bounds of the same angles
  };
  bool isSliver(del3d::TetId t, const SliverAngles& a) const;
  void setGuardEuclidean(bool on) { guardEuclidean_ = on; }
  bool guardEuclidean() const { return guardEuclidean_; }

 private:
  const del3d::TetMesh& mesh_;
  const ControlSpace3d& cs_;
  /// metric, or with the guard on the smallest of metric and the Euclidean terms of p
  /// (`euclidean`: metric is p's Euclidean value already).
  double guarded(double metric, const Vec3* p, bool euclidean) const;
  bool isotropic(const std::uint32_t* v) const { return iso_[v[0]] && iso_[v[1]] && iso_[v[2]] && iso_[v[3]]; }
  void setMetric(std::size_t v, const Mat3& m);

  std::vector<Mat3> m_;
  std::vector<std::uint8_t> iso_;
  bool guardEuclidean_ = false;
};

}  // namespace aniso::improve3d
