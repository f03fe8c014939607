#pragma once
// ParametricSurface — the thesis' surface interface (fig. 6.1, sec. 6.2.1, eq. 2.2).
//
// A surface patch p : S ⊂ R² → R³, s = (u, v). Implementations provide the point and the
// first and second partial derivatives; everything else (normal, fundamental forms,
// principal curvatures, parameterization tensor M_p, projection) has a general
// implementation here that an implementation may override when it knows better.
//
// Implemented by the analytic surfaces in this folder and by the OCCT adapter in cad/.
// Thread safety: const methods may keep evaluation caches (OCCT's B-spline cache does);
// a thread that evaluates concurrently must use its own clone().
#include <memory>
#include <optional>

#include "mesher/core/Types.h"

namespace aniso {

/// Point and first derivatives at (u,v).
struct SurfaceD1 {
  Vec3 p, pu, pv;
};

/// Point, first and second derivatives at (u,v).
struct SurfaceD2 {
  Vec3 p, pu, pv, puu, puv, pvv;
};

/// Principal curvatures and directions (sec. 2.4.2, eq. 2.38–2.40).
/// k1 <= k2 (signed, with respect to normal()); dir1/dir2 are the principal directions as
/// unit vectors in the parametric plane (u,v) (not normalised in any metric) and d3_1,
/// d3_2 their images D p(dir) in R³, normalised. For an umbilic point the directions are
/// the u direction and its G-orthogonal complement.
struct PrincipalCurvatures {
  double k1 = 0, k2 = 0;
  Vec2 dir1 = Vec2::UnitX(), dir2 = Vec2::UnitY();
  Vec3 d3_1 = Vec3::UnitX(), d3_2 = Vec3::UnitY();
  /// max(|k1|, |k2|)
  double maxAbs() const;
};

/// The parametric domain of a surface: the rectangle of its natural parameters and its
/// periodicity. Unbounded surfaces (planes) report the bounds given at construction.
struct SurfaceDomain {
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  bool uPeriodic = false, vPeriodic = false;
  double uPeriod = 0, vPeriod = 0;
};

class ParametricSurface {
 public:
  virtual ~ParametricSurface() = default;

  // ---- what implementations must provide ----
  /// Point p(u,v).
  virtual Vec3 point(const Vec2& uv) const = 0;
  /// Point and first derivatives.
  virtual SurfaceD1 d1(const Vec2& uv) const = 0;
  /// Point, first and second derivatives.
  virtual SurfaceD2 d2(const Vec2& uv) const = 0;
  /// Natural domain and periodicity.
  virtual SurfaceDomain domain() const = 0;
  /// An independent copy for use in another thread.
  virtual std::unique_ptr<ParametricSurface> clone() const = 0;

  /// True when p is affine in (u, v) (a plane with a linear parameterization): then a
  /// triangle's orientation in (u, v) is its orientation on the surface, and tests in 3D
  /// can be skipped. Conservative default: false.
  virtual bool affine() const { return false; }

  // ---- general methods (override where a faster exact form exists) ----
  /// Unit normal n = pu × pv / |pu × pv|. At a singular point (|pu × pv| tiny) the normal
  /// is taken from a nearby regular point towards the domain centre; never NaN.
  virtual Vec3 normal(const Vec2& uv) const;

  /// First fundamental form G (eq. 2.7).
  Mat2 firstFundamentalForm(const Vec2& uv) const;
  /// Second fundamental form B (eq. 2.37), with respect to normal().
  Mat2 secondFundamentalForm(const Vec2& uv) const;

  /// Principal curvatures and directions from det(B − χG) = 0 (eq. 2.38–2.40).
  virtual PrincipalCurvatures curvature(const Vec2& uv) const;

  /// Parameterization tensor M_p (eq. 2.8): the symmetric positive-definite square root of
  /// G, with the degenerate-parameterization guard of sec. 2.2.1: g11 and g22 are raised
  /// to at least gMin (the thesis writes min(), which cannot be what is meant: the point
  /// of the guard is that g_ii must not vanish). gMin is an absolute value in model
  /// units squared; callers pass a value relative to the model size.
  Mat2 parameterizationTensor(const Vec2& uv, double gMin) const;

  /// Projection of a 3D point onto the surface (getParameter, sec. 6.2.1): the (u,v)
  /// minimising |p(u,v) − x|, found by a damped Gauss–Newton iteration from `start`.
  /// Periodic parameters are left unwrapped (the result stays near `start`), non-periodic
  /// ones are clamped to the domain. Returns the best (u,v) found; never throws.
  virtual Vec2 project(const Vec3& x, const Vec2& start) const;
};

using SurfacePtr = std::shared_ptr<const ParametricSurface>;

}  // namespace aniso
