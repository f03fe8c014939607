#include "mesher/geometry/ExpressionSurface.h"

#include <muParser.h>

#include <cmath>
#include <numbers>

#include "mesher/core/Error.h"

namespace aniso {

namespace {

constexpr double kStep1 = 1e-4;  ///< first-derivative step / domain extent
constexpr double kStep2 = 3e-4;  ///< second-derivative step / domain extent
constexpr const char* kNames[3] = {"x", "y", "z"};

}  // namespace

struct ExpressionSurface::Evaluator {
  double u = 0, v = 0;
  mu::Parser parser[3];

  Vec3 at(double uu, double vv) {
    u = uu;
    v = vv;
    return Vec3(parser[0].Eval(), parser[1].Eval(), parser[2].Eval());
  }
};

ExpressionSurface::ExpressionSurface(const std::string& x, const std::string& y,
                                     const std::string& z, const SurfaceDomain& domain)
    : expr_{x, y, z}, dom_(domain), eval_(std::make_unique<Evaluator>()) {
  const double eu = dom_.u1 - dom_.u0, ev = dom_.v1 - dom_.v0;
  if (!(eu > 0) || !(ev > 0) || !std::isfinite(eu) || !std::isfinite(ev))
    throw InputError("expression surface: empty or non-finite parameter rectangle");
  h1u_ = kStep1 * eu; h1v_ = kStep1 * ev;
  h2u_ = kStep2 * eu; h2v_ = kStep2 * ev;
  const Vec2 probes[5] = {{0.5 * (dom_.u0 + dom_.u1), 0.5 * (dom_.v0 + dom_.v1)},
                          {dom_.u0, dom_.v0}, {dom_.u1, dom_.v0}, {dom_.u0, dom_.v1}, {dom_.u1, dom_.v1}};
  for (int i = 0; i < 3; ++i) {
    const std::string what = std::string("expression surface: ") + kNames[i] + "(u,v) = \"" + expr_[i] + "\"";
    mu::Parser& p = eval_->parser[i];
    try {
      p.DefineVar("u", &eval_->u);
      p.DefineVar("v", &eval_->v);
      p.DefineConst("pi", std::numbers::pi);
      p.SetExpr(expr_[i]);
      for (const Vec2& q : probes) {
        eval_->u = q.x();
        eval_->v = q.y();
        if (!std::isfinite(p.Eval()))
          throw InputError(what + " is not finite at (u,v) = (" + std::to_string(q.x()) + ", " +
                           std::to_string(q.y()) + ")");
      }
    } catch (const mu::Parser::exception_type& e) {
      throw InputError(what + " is invalid: " + e.GetMsg());
    }
  }
}

ExpressionSurface::ExpressionSurface(const ExpressionSurface& other)
    : ExpressionSurface(other.expr_[0], other.expr_[1], other.expr_[2], other.dom_) {}

ExpressionSurface::~ExpressionSurface() = default;

Vec3 ExpressionSurface::point(const Vec2& uv) const { return eval_->at(uv.x(), uv.y()); }

SurfaceD1 ExpressionSurface::d1(const Vec2& uv) const {
  Evaluator& e = *eval_;
  const double u = uv.x(), v = uv.y(), hu = h1u_, hv = h1v_;
  const Vec3 p = e.at(u, v);
  // f' ≈ (−f(+2h) + 8 f(+h) − 8 f(−h) + f(−2h)) / 12h
  const Vec3 pu = (-e.at(u + 2 * hu, v) + 8 * e.at(u + hu, v) - 8 * e.at(u - hu, v) + e.at(u - 2 * hu, v)) / (12 * hu);
  const Vec3 pv = (-e.at(u, v + 2 * hv) + 8 * e.at(u, v + hv) - 8 * e.at(u, v - hv) + e.at(u, v - 2 * hv)) / (12 * hv);
  return {p, pu, pv};
}

SurfaceD2 ExpressionSurface::d2(const Vec2& uv) const {
  Evaluator& e = *eval_;
  const SurfaceD1 first = d1(uv);
  const double u = uv.x(), v = uv.y(), hu = h2u_, hv = h2v_;
  const Vec3 p = first.p;
  // f'' ≈ (−f(+2h) + 16 f(+h) − 30 f + 16 f(−h) − f(−2h)) / 12h²
  const Vec3 puu = (-e.at(u + 2 * hu, v) + 16 * e.at(u + hu, v) - 30 * p + 16 * e.at(u - hu, v) -
                    e.at(u - 2 * hu, v)) / (12 * hu * hu);
  const Vec3 pvv = (-e.at(u, v + 2 * hv) + 16 * e.at(u, v + hv) - 30 * p + 16 * e.at(u, v - hv) -
                    e.at(u, v - 2 * hv)) / (12 * hv * hv);
  // Mixed: D(k) = (f(+k,+k) − f(+k,−k) − f(−k,+k) + f(−k,−k)) / 4k², Richardson (4D(h) − D(2h))/3.
  const auto mixed = [&](double s) {
    const double a = s * hu, b = s * hv;
    return Vec3((e.at(u + a, v + b) - e.at(u + a, v - b) - e.at(u - a, v + b) + e.at(u - a, v - b)) /
                (4 * a * b));
  };
  const Vec3 puv = (4 * mixed(1) - mixed(2)) / 3;
  return {p, first.pu, first.pv, puu, puv, pvv};
}

SurfaceDomain ExpressionSurface::domain() const { return dom_; }

std::unique_ptr<ParametricSurface> ExpressionSurface::clone() const {
  return std::make_unique<ExpressionSurface>(*this);
}

}  // namespace aniso
