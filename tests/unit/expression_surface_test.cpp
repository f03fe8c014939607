// ExpressionSurface: the thesis' SURF0 (eq. A.2) against its analytic derivatives, error
// reporting, and copies with fresh parsers.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mesher/core/Error.h"
#include "mesher/geometry/ExpressionSurface.h"

using namespace aniso;

namespace {

// SURF0 (eq. A.2): z = 1.5 e^{−0.001(u²+v²)} sin(2u) cos(0.2v), u, v ∈ [−6, 6].
const char* kSurf0 = "1.5*exp(-0.001*(u^2+v^2))*sin(2*u)*cos(0.2*v)";

struct Surf0 {
  double z, zu, zv, zuu, zuv, zvv;
};

Surf0 surf0Truth(double u, double v) {
  const double e = 1.5 * std::exp(-0.001 * (u * u + v * v));
  const double s = std::sin(2 * u), c = std::cos(2 * u), cv = std::cos(0.2 * v), sv = std::sin(0.2 * v);
  // z = e(u,v) S(u) C(v) with e_u = −0.002 u e, e_v = −0.002 v e.
  const double a = -0.002 * u, b = -0.002 * v;
  const double S = s, Su = 2 * c, Suu = -4 * s, C = cv, Cv = -0.2 * sv, Cvv = -0.04 * cv;
  Surf0 t;
  t.z = e * S * C;
  t.zu = e * (a * S + Su) * C;
  t.zv = e * S * (b * C + Cv);
  // e_uu = e (a² − 0.002), e_vv = e (b² − 0.002), e_uv = e a b.
  t.zuu = e * ((a * a - 0.002) * S + 2 * a * Su + Suu) * C;
  t.zvv = e * S * ((b * b - 0.002) * C + 2 * b * Cv + Cvv);
  t.zuv = e * (a * S + Su) * (b * C + Cv);
  return t;
}

}  // namespace

TEST(ExpressionSurface, Surf0MatchesAnalyticDerivatives) {
  const ExpressionSurface s("u", "v", kSurf0, SurfaceDomain{-6, 6, -6, 6});
  for (double u : {-5.9, -2.3, 0.0, 0.77, 4.1, 6.0}) {
    for (double v : {-6.0, -1.1, 0.3, 5.5}) {
      const Surf0 t = surf0Truth(u, v);
      const SurfaceD2 d = s.d2({u, v});
      EXPECT_NEAR(d.p.z(), t.z, 1e-14);
      EXPECT_LT((d.pu - Vec3(1, 0, t.zu)).norm(), 1e-9) << u << " " << v;
      EXPECT_LT((d.pv - Vec3(0, 1, t.zv)).norm(), 1e-9);
      EXPECT_LT((d.puu - Vec3(0, 0, t.zuu)).norm(), 1e-7);
      EXPECT_LT((d.puv - Vec3(0, 0, t.zuv)).norm(), 1e-7);
      EXPECT_LT((d.pvv - Vec3(0, 0, t.zvv)).norm(), 1e-7);
      const SurfaceD1 e = s.d1({u, v});
      EXPECT_LT((e.pu - d.pu).norm(), 1e-15);
    }
  }
}

TEST(ExpressionSurface, CurvatureOfAParaboloid) {
  // z = (u² + v²)/2: umbilic with k = 1 at the origin (normal +z).
  const ExpressionSurface s("u", "v", "(u^2+v^2)/2", SurfaceDomain{-1, 1, -1, 1});
  const PrincipalCurvatures pc = s.curvature({0, 0});
  EXPECT_NEAR(pc.k1, 1, 1e-7);
  EXPECT_NEAR(pc.k2, 1, 1e-7);
}

TEST(ExpressionSurface, PiAndDomainAreReported) {
  SurfaceDomain dom{0, 2 * std::acos(-1.0), -1, 1, true, false, 2 * std::acos(-1.0), 0};
  const ExpressionSurface cyl("cos(u)", "sin(u)", "v", dom);
  EXPECT_TRUE(cyl.domain().uPeriodic);
  EXPECT_NEAR(cyl.point({0.5 * std::acos(-1.0), 0}).y(), 1, 1e-15);
  const ExpressionSurface withPi("u", "v", "sin(pi*u)", SurfaceDomain{0, 1, 0, 1});
  EXPECT_NEAR(withPi.point({0.5, 0}).z(), 1, 1e-15);
}

TEST(ExpressionSurface, BadExpressionThrowsInputErrorNamingIt) {
  const SurfaceDomain dom{0, 1, 0, 1};
  try {
    ExpressionSurface s("u", "v", "sin(u*)", dom);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("z(u,v)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("sin(u*)"), std::string::npos) << msg;
  }
  EXPECT_THROW(ExpressionSurface("u+w", "v", "0", dom), InputError);   // unknown variable
  EXPECT_THROW(ExpressionSurface("u", "", "0", dom), InputError);      // empty
  EXPECT_THROW(ExpressionSurface("u", "v", "foo(u)", dom), InputError);  // unknown function
  EXPECT_THROW(ExpressionSurface("u", "v", "sqrt(u-2)", dom), InputError);  // NaN on the domain
  EXPECT_THROW(ExpressionSurface("u", "v", "0", SurfaceDomain{1, 0, 0, 1}), InputError);
}

TEST(ExpressionSurface, CopiesAndClonesHaveTheirOwnParsers) {
  const SurfaceDomain dom{-6, 6, -6, 6};
  auto original = std::make_unique<ExpressionSurface>("u", "v", kSurf0, dom);
  const std::unique_ptr<ParametricSurface> clone = original->clone();
  const ExpressionSurface copy(*original);
  const Vec3 expected = original->point({1.0, 2.0});
  original.reset();  // a copy bound to the original's variables would now read freed memory
  EXPECT_LT((clone->point({1.0, 2.0}) - expected).norm(), 1e-15);
  EXPECT_LT((copy.point({1.0, 2.0}) - expected).norm(), 1e-15);
  // Interleaved evaluation of two copies does not mix their variables.
  const ExpressionSurface other(copy);
  const Vec3 a = copy.point({0.5, 0.5});
  const Vec3 b = other.point({-3, 4});
  EXPECT_LT((copy.point({0.5, 0.5}) - a).norm(), 1e-15);
  EXPECT_NEAR(b.z(), surf0Truth(-3, 4).z, 1e-14);
  EXPECT_EQ(copy.expression(2), kSurf0);
}
