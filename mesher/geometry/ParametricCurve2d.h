#pragma once
// ParametricCurve2d — a contour curve in the parametric space of a surface (a "pcurve"),
// the thesis' fig. 6.2, sec. 6.2.2, eq. 2.44.
//
// c_p : C ⊂ R → S ⊂ R². Implementations provide the point and two derivatives; the
// projection, lengths, polyline and the curvature of the 3D image p∘c_p (eq. 2.45) are
// general. Thread safety as for ParametricSurface: use clone() per thread.
#include <functional>
#include <memory>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

class ParametricSurface;

struct Curve2dD2 {
  Vec2 p, d1, d2;
};

class ParametricCurve2d {
 public:
  virtual ~ParametricCurve2d() = default;

  // ---- what implementations must provide ----
  virtual Vec2 point(double t) const = 0;
  /// Point, first and second derivatives with respect to t.
  virtual Curve2dD2 d2(double t) const = 0;
  /// Natural parameter range (may be larger than the range an edge uses).
  virtual double tMin() const = 0;
  virtual double tMax() const = 0;
  virtual std::unique_ptr<ParametricCurve2d> clone() const = 0;

  // ---- general methods ----
  /// Parameter of the point of the curve nearest to p within [t0, t1], starting from ts
  /// (getParameter: bracketing, bisection and Newton). Never throws.
  virtual double project(const Vec2& p, double ts, double t0, double t1) const;

  /// Length in the parametric plane of the piece [t0, t1] (adaptive Gauss quadrature).
  double length(double t0, double t1) const;

  /// Length of the piece [t0, t1] in a metric: the integral of |M(c(t)) c'(t)| dt where
  /// `transform` returns the 2×2 transformation tensor at a parametric point (a control
  /// space, ch. 3, passes its metric here; with M = M_p the result is the length in R³).
  double length(double t0, double t1, const std::function<Mat2(const Vec2&)>& transform) const;

  /// Parameters of a polyline approximation of [t0, t1]: t0 first, t1 last, refined until
  /// the chord deviation is at most `tol` times the chord length, measured in 3D on
  /// `surface` if given, else in the parametric plane.
  std::vector<double> polyline(double t0, double t1, const ParametricSurface* surface,
                               double tol = 1e-3) const;

  /// Curvature κ of the 3D curve p∘c_p at t (eq. 2.45): |c' × c''| / |c'|³.
  double curvature(double t, const ParametricSurface& surface) const;
};

using Curve2dPtr = std::shared_ptr<const ParametricCurve2d>;

}  // namespace aniso
