#include "mesher/control/MetricExpression.h"

#include <muParser.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

#include "mesher/control/PerThreadState.h"
#include "mesher/core/Error.h"

namespace aniso {
namespace {

constexpr const char* kNames2d[3] = {"alpha", "h1", "h2"};
constexpr const char* kNames3d[9] = {"h1", "h2", "h3", "e1.x", "e1.y", "e1.z", "e2.x", "e2.y", "e2.z"};

/// Parsers over variables a, b, c (aliases as given) for a list of expressions.
template <int N>
struct ParserSet {
  double vars[3] = {0, 0, 0};
  std::vector<mu::Parser> parsers;
};

template <int N>
std::unique_ptr<ParserSet<N>> makeParsers(const std::vector<std::string>& exprs,
                                          const std::vector<std::pair<const char*, int>>& variables) {
  auto set = std::make_unique<ParserSet<N>>();
  set->parsers.resize(exprs.size());
  for (std::size_t i = 0; i < exprs.size(); ++i) {
    mu::Parser& p = set->parsers[i];
    for (const auto& [name, index] : variables) p.DefineVar(name, &set->vars[index]);
    p.DefineConst("pi", std::numbers::pi);
    p.SetExpr(exprs[i]);
  }
  return set;
}

/// Parses every expression once (muParser parses lazily on the first Eval) and throws
/// InputError naming the first one it rejects.
template <int N>
void checkSyntax(ParserSet<N>& set, const std::vector<std::string>& exprs, const char* const* names) {
  for (std::size_t i = 0; i < exprs.size(); ++i) {
    try {
      set.parsers[i].Eval();
      if (set.parsers[i].GetNumResults() != 1)
        throw InputError(std::string("analytic metric: ") + names[i] + " = \"" + exprs[i] +
                         "\" must give exactly one value");
    } catch (const mu::Parser::exception_type& e) {
      throw InputError(std::string("analytic metric: ") + names[i] + " = \"" + exprs[i] + "\" is invalid: " + e.GetMsg());
    }
  }
}

template <int D>
std::string pointText(const double* x, const char* names) {
  std::ostringstream s;
  s.precision(10);
  s << "(";
  for (int k = 0; k < D; ++k) s << (k ? ", " : "") << names[k];
  s << ") = (";
  for (int k = 0; k < D; ++k) s << (k ? ", " : "") << x[k];
  s << ")";
  return s.str();
}

template <int N>
double evaluate(ParserSet<N>& set, std::size_t i, const std::vector<std::string>& exprs, const char* const* names) {
  try {
    return set.parsers[i].Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw MeshingError(std::string("analytic metric: ") + names[i] + " = \"" + exprs[i] + "\" failed at " +
                       pointText<N>(set.vars, N == 2 ? "uv" : "xyz") + ": " + e.GetMsg());
  }
}

[[noreturn]] void badValue(const char* name, double value, const std::string& expr, const std::string& where,
                           const char* requirement) {
  std::ostringstream s;
  s.precision(10);
  s << "analytic metric: " << name << " = " << value << " at " << where << " (from \"" << expr << "\") is not "
    << requirement;
  throw MeshingError(s.str());
}

}  // namespace

// ---- 2D ----

struct MetricExpression2d::Impl {
  std::vector<std::string> exprs;
  std::array<std::string, 3> expr;
  PerThreadState<ParserSet<2>> states;

  explicit Impl(std::array<std::string, 3> e)
      : exprs(e.begin(), e.end()), expr(std::move(e)), states([this] {
          return makeParsers<2>(exprs, {{"u", 0}, {"v", 1}, {"x", 0}, {"y", 1}});
        }) {}
};

MetricExpression2d::MetricExpression2d(std::string alpha, std::string h1, std::string h2) {
  auto impl = std::make_shared<Impl>(std::array<std::string, 3>{std::move(alpha), std::move(h1), std::move(h2)});
  try {
    checkSyntax(impl->states.local(), impl->exprs, kNames2d);
  } catch (const mu::Parser::exception_type& e) {  // DefineVar / SetExpr errors
    throw InputError(std::string("analytic metric: invalid expression: ") + e.GetMsg());
  }
  impl_ = std::move(impl);
}

const std::string& MetricExpression2d::expression(int i) const { return impl_->expr.at(i); }

Metric2d MetricExpression2d::operator()(const Vec2& uv) const {
  ParserSet<2>& s = impl_->states.local();
  s.vars[0] = uv.x();
  s.vars[1] = uv.y();
  double v[3];
  for (int i = 0; i < 3; ++i) v[i] = evaluate(s, i, impl_->exprs, kNames2d);
  const auto where = [&s] { return pointText<2>(s.vars, "uv"); };
  if (!std::isfinite(v[0])) badValue("alpha", v[0], impl_->expr[0], where(), "finite");
  for (int i = 1; i < 3; ++i)
    if (!(std::isfinite(v[i]) && v[i] > 0)) badValue(kNames2d[i], v[i], impl_->expr[i], where(), "finite and positive");
  return Metric2d::fromAngle(v[0], v[1], v[2]);
}

// ---- 3D ----

struct MetricExpression3d::Impl {
  std::vector<std::string> exprs;
  bool directions;
  PerThreadState<ParserSet<3>> states;

  Impl(std::vector<std::string> e, bool dirs)
      : exprs(std::move(e)), directions(dirs), states([this] {
          return makeParsers<3>(exprs, {{"x", 0}, {"y", 1}, {"z", 2}});
        }) {}
};

namespace {
std::shared_ptr<MetricExpression3d::Impl> make3d(std::vector<std::string> exprs, bool directions) {
  auto impl = std::make_shared<MetricExpression3d::Impl>(std::move(exprs), directions);
  try {
    checkSyntax(impl->states.local(), impl->exprs, kNames3d);
  } catch (const mu::Parser::exception_type& e) {
    throw InputError(std::string("analytic metric: invalid expression: ") + e.GetMsg());
  }
  return impl;
}
}  // namespace

MetricExpression3d::MetricExpression3d(std::array<std::string, 3> h)
    : impl_(make3d({std::move(h[0]), std::move(h[1]), std::move(h[2])}, false)) {}

MetricExpression3d::MetricExpression3d(std::array<std::string, 3> h, std::array<std::string, 3> e1,
                                       std::array<std::string, 3> e2)
    : impl_(make3d({h[0], h[1], h[2], e1[0], e1[1], e1[2], e2[0], e2[1], e2[2]}, true)) {}

bool MetricExpression3d::hasDirections() const { return impl_->directions; }

Metric3d MetricExpression3d::operator()(const Vec3& x) const {
  ParserSet<3>& s = impl_->states.local();
  for (int k = 0; k < 3; ++k) s.vars[k] = x(k);
  const std::size_t n = impl_->exprs.size();
  double v[9];
  for (std::size_t i = 0; i < n; ++i) v[i] = evaluate(s, i, impl_->exprs, kNames3d);
  const auto where = [&s] { return pointText<3>(s.vars, "xyz"); };
  for (int i = 0; i < 3; ++i)
    if (!(std::isfinite(v[i]) && v[i] > 0)) badValue(kNames3d[i], v[i], impl_->exprs[i], where(), "finite and positive");
  if (!impl_->directions) return Metric3d::fromDirections(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), v[0], v[1], v[2]);
  const Vec3 e1(v[3], v[4], v[5]), e2(v[6], v[7], v[8]);
  if (!(e1.allFinite() && e1.norm() > 0))
    throw MeshingError("analytic metric: direction e1 at " + where() + " is zero or not finite");
  const Vec3 d1 = e1.normalized();
  const Vec3 o2 = e2 - e2.dot(d1) * d1;
  if (!(e2.allFinite() && o2.norm() > 1e-9 * e2.norm()))
    throw MeshingError("analytic metric: direction e2 at " + where() + " is zero, not finite or parallel to e1");
  const Vec3 d2 = o2.normalized();
  return Metric3d::fromDirections(d1, d2, d1.cross(d2), v[0], v[1], v[2]);
}

}  // namespace aniso
