#pragma once
// ExpressionSurface — p(u,v) = (x(u,v), y(u,v), z(u,v)) given as muParser expression
// strings over a parameter rectangle: the analytic test surfaces of the thesis (appendix A,
// eq. A.2–A.4, e.g. SURF0: x = "u", y = "v", z = "1.5*exp(-0.001*(u^2+v^2))*sin(2*u)*cos(0.2*v)"
// on [−6, 6]²).
//
// Derivatives are fourth-order central finite differences with steps relative to the domain
// size (first derivatives 1e-4 × extent, second derivatives 3e-4 × extent; mixed by
// Richardson extrapolation), accurate to about 1e-9 relative for smooth expressions. The
// expressions must therefore be defined a little beyond the rectangle as well.
// Not thread-safe (the parsers hold the evaluation variables): use clone() per thread.
#include <array>
#include <memory>
#include <string>

#include "mesher/geometry/ParametricSurface.h"

namespace aniso {

class ExpressionSurface final : public ParametricSurface {
 public:
  /// Variables u and v; the constant pi and muParser's built-in functions (sin, exp, sqrt,
  /// ^, ...) are available. `domain` gives the rectangle and periodicity. Throws
  /// InputError naming the coordinate and its expression when muParser rejects one or it
  /// is not finite at the centre or a corner of the rectangle, and when the rectangle is
  /// empty or not finite.
  ExpressionSurface(const std::string& x, const std::string& y, const std::string& z,
                    const SurfaceDomain& domain);
  /// A copy parses the expressions again (fresh parsers bound to its own variables).
  ExpressionSurface(const ExpressionSurface& other);
  ExpressionSurface& operator=(const ExpressionSurface&) = delete;
  ~ExpressionSurface() override;

  Vec3 point(const Vec2& uv) const override;
  SurfaceD1 d1(const Vec2& uv) const override;
  SurfaceD2 d2(const Vec2& uv) const override;
  SurfaceDomain domain() const override;
  std::unique_ptr<ParametricSurface> clone() const override;

  /// The expression of coordinate i (0: x, 1: y, 2: z).
  const std::string& expression(int i) const { return expr_.at(i); }

 private:
  struct Evaluator;  // the three parsers and the variables u, v they point to
  std::array<std::string, 3> expr_;
  SurfaceDomain dom_;
  std::unique_ptr<Evaluator> eval_;
  double h1u_, h1v_, h2u_, h2v_;  ///< finite-difference steps
};

}  // namespace aniso
