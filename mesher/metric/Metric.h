#pragma once
// Metric<D> — an anisotropic metric in the thesis' symmetric transformation-tensor form
// (sec. 2.2): M = R S Rᵀ with R the rotation whose columns are the main directions e_i and
// S = diag(1/h_i), h_i the requested edge lengths along e_i (eq. 2.4 in 2D, eq. 2.15 in 3D).
//
// Relation to the metric tensor (eq. 2.1, 2.19): 𝓜 = M Mᵀ = M² = R diag(1/h_i²) Rᵀ, so M is
// the unique symmetric positive-definite square root of 𝓜.
//
// What M does (eq. 2.10, 2.11, 2.17): a point P is mapped to metric space as P^M = M P,
// and the metric length of a vector v is |M v| (the length of v measured in units of the
// requested edge length along v). The unit ball {v : |M v| ≤ 1} is the ellipse
// (ellipsoid) with semi-axes h_i along e_i.
//
// Which space: a Metric2d used for surface meshing is the *sizing component* M_s of
// eq. 2.9; it acts on vectors of the space S^R (eq. 2.12, parametric vectors already
// multiplied by M_p, i.e. an isometric copy of the tangent plane). The full surface
// transformation M = M_s M_p is not symmetric and is a plain Mat2 (see SurfaceMetric.h).
// A Metric3d acts directly on physical vectors (eq. 2.16).
//
// Invariant: the stored matrix is finite, exactly symmetric and positive definite. Every
// factory checks its input and throws aniso::MeshingError (never NaN) when it is not.
// Value type, no heap allocation; the hot functions (apply, length) are inline.
#include <Eigen/LU>

#include "mesher/core/Types.h"

namespace aniso {

/// Main directions and lengths of a metric (eigen-decomposition of M).
template <int D>
struct MetricAxes {
  Eigen::Matrix<double, D, D> directions;  ///< orthonormal columns e_i (right-handed in 3D)
  Eigen::Matrix<double, D, 1> lengths;     ///< h_i along e_i, ascending (h_1 the smallest)
};

/// (α, h1, h2) of a 2D metric: h1 ≤ h2, h1 along (cos α, sin α), α ∈ (−π/2, π/2].
struct MetricAngle2d {
  double alpha = 0, h1 = 1, h2 = 1;
};

template <int D>
class Metric {
  static_assert(D == 2 || D == 3, "Metric<D> exists for D = 2 and D = 3");

 public:
  using Vec = Eigen::Matrix<double, D, 1>;
  using Mat = Eigen::Matrix<double, D, D>;

  /// The identity: unit edge lengths in every direction.
  Metric() = default;
  static Metric identity() { return Metric(); }
  /// Isotropic metric M = I / h. Throws when h is not finite and > 0.
  static Metric isotropic(double h);
  /// Eq. 2.4: M = R(α) diag(1/h1, 1/h2) R(α)ᵀ, h1 along (cos α, sin α). Any h1, h2 > 0.
  static Metric fromAngle(double alpha, double h1, double h2)
    requires(D == 2);
  /// Eq. 2.15: M = Σ e_i e_iᵀ / h_i. The directions are normalised and must be mutually
  /// orthogonal (|e_i·e_j| ≤ 1e-6 after normalisation); lengths finite and > 0.
  static Metric fromDirections(const Vec3& e1, const Vec3& e2, const Vec3& e3, double h1,
                               double h2, double h3)
    requires(D == 3);
  /// M = E diag(1/h) Eᵀ for orthonormal columns E (tolerance 1e-6) and lengths h > 0.
  static Metric fromAxes(const Mat& directions, const Vec& lengths);
  /// From a transformation tensor given as a matrix: must be finite, symmetric (relative
  /// asymmetry ≤ 1e-9, then symmetrised) and positive definite.
  static Metric fromTransformation(const Mat& m);
  /// From a metric tensor 𝓜 (finite, symmetric, SPD): M = 𝓜^{1/2} (sec. 2.3.2, step 3).
  static Metric fromTensor(const Mat& tensor);

  /// The symmetric transformation tensor M.
  const Mat& matrix() const { return m_; }
  /// Metric tensor 𝓜 = M Mᵀ (eq. 2.19).
  Mat tensor() const { return m_ * m_; }
  /// M⁻¹ = R diag(h_i) Rᵀ (symmetric, SPD): the "length tensor" interpolated by eq. 2.18.
  Mat inverseMatrix() const;
  /// Eigen-decomposition back to directions and lengths (inverse of fromAxes).
  MetricAxes<D> axes() const;
  /// Eigen-decomposition back to (α, h1, h2), h1 ≤ h2 (inverse of fromAngle).
  MetricAngle2d angleLengths() const
    requires(D == 2);
  /// s·M: every requested length divided by s. Throws unless s is finite and > 0.
  Metric scaled(double s) const;

  /// P^M = M P (eq. 2.10, 2.17).
  Vec apply(const Vec& p) const { return m_ * p; }
  /// Metric length |M v| of a vector.
  double length(const Vec& v) const { return (m_ * v).norm(); }
  /// d_M(P1, P2) = |M (P2 − P1)| for a metric constant along the segment (eq. 2.11).
  double distance(const Vec& a, const Vec& b) const { return length(b - a); }
  /// Requested edge length along the direction of v (v ≠ 0): |v| / |M v|.
  double lengthAlong(const Vec& v) const { return v.norm() / length(v); }
  /// det M = Π 1/h_i (volume of the unit ball in metric space relative to physical).
  double determinant() const { return m_.determinant(); }

 private:
  explicit Metric(const Mat& m) : m_(m) {}
  Mat m_ = Mat::Identity();
};

using Metric2d = Metric<2>;
using Metric3d = Metric<3>;

extern template class Metric<2>;
extern template class Metric<3>;

}  // namespace aniso
