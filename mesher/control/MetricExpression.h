#pragma once
// Metric fields given as muParser expressions — the user's analytic form of a metric.
//
// MetricExpression2d: the angle α and the lengths h1, h2 of eq. 2.4 (appendix A, eq. A.1;
// e.g. AN1: α = "pi/6", h1 = "0.01", h2 = "0.0101 - 0.005*u"), expressions in u and v
// (x and y are aliases of u and v for planar domains). The result is
// Metric2d::fromAngle(α, h1, h2): h1 along (cos α, sin α).
// MetricExpression3d: h1, h2, h3 in x, y, z, optionally with the directions e1 and e2 as
// three expressions each (e2 is made orthogonal to e1, e3 = e1 × e2); without directions
// h1, h2, h3 are along the x, y, z axes (eq. 2.15).
//
// Both define the constants pi and _pi (muParser's own) and muParser's built-in functions
// (sin, cos, exp, sqrt, abs, min, max, ^, ...).
// Errors: an expression muParser rejects (syntax, unknown name) throws InputError naming
// the quantity and the expression, at construction. Evaluation that gives a non-finite
// angle or direction, or a length that is not finite and positive, throws MeshingError
// naming the point, the quantity and the expression.
// Thread safety: operator() may be called concurrently; each thread evaluates with its own
// parsers (PerThreadState.h). Copies are cheap and share the expressions.
#include <array>
#include <memory>
#include <string>

#include "mesher/metric/Metric.h"

namespace aniso {

class MetricExpression2d {
 public:
  MetricExpression2d(std::string alpha, std::string h1, std::string h2);
  Metric2d operator()(const Vec2& uv) const;
  /// 0: α, 1: h1, 2: h2.
  const std::string& expression(int i) const;

  struct Impl;

 private:
  std::shared_ptr<const Impl> impl_;
};

class MetricExpression3d {
 public:
  /// Lengths along the coordinate axes.
  explicit MetricExpression3d(std::array<std::string, 3> h);
  /// Lengths along e1, e2 (orthogonalised against e1) and e3 = e1 × e2.
  MetricExpression3d(std::array<std::string, 3> h, std::array<std::string, 3> e1, std::array<std::string, 3> e2);
  Metric3d operator()(const Vec3& x) const;
  bool hasDirections() const;

  struct Impl;

 private:
  std::shared_ptr<const Impl> impl_;
};

}  // namespace aniso
