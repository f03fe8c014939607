// Analytic and identity control spaces (sec. 6.3.1): callables, muParser expressions,
// errors, sub-domains, parameterization tensor, thread safety.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "mesher/control/CSAnalytic2d.h"
#include "mesher/control/CSAnalytic3d.h"
#include "mesher/control/CSIdentity.h"
#include "mesher/core/Error.h"
#include "mesher/geometry/SphereSurface.h"
#include "mesher/metric/MetricComparison.h"
#include "control_fixtures.h"

using namespace aniso;
using namespace aniso::testing;

namespace {

/// The message of the exception f throws (empty if none or another type).
template <class E, class F>
std::string messageOf(F f) {
  try {
    f();
  } catch (const E& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST(ControlAnalytic, AN1ExpressionsGiveTheThesisMetric) {
  const CSAnalytic2d cs(box2(0, 0, 2, 1), "pi/6", "0.01", "0.0101-0.005*u");
  for (const Vec2& p : {Vec2(0, 0), Vec2(1, 0.5), Vec2(2, 1)}) {
    const Metric2d expected = Metric2d::fromAngle(kPi / 6, 0.01, 0.0101 - 0.005 * p.x());
    const SurfaceMetricAt m = cs.getMetric(p);
    EXPECT_LT((m.sizing.matrix() - expected.matrix()).norm(), 1e-9 * expected.matrix().norm());
    EXPECT_EQ(m.parameterization, Mat2::Identity());
  }
  // muParser's own _pi and the x, y aliases work as well.
  const MetricExpression2d e("_pi/6 + 0*x*y", "0.01", "0.0101-0.005*u");
  EXPECT_LT(metricDifference(e(Vec2(1.5, 0.2)), cs.getMetric(Vec2(1.5, 0.2)).sizing), 1e-12);
  // Outside the domain: the nearest point of the domain (h2 stays positive).
  EXPECT_LT(metricDifference(cs.getMetric(Vec2(5, 0.5)).sizing, cs.getMetric(Vec2(2, 0.5)).sizing), 1e-12);
}

TEST(ControlAnalytic, BadExpressionsThrowInputErrorNamingThem) {
  const std::string msg = messageOf<InputError>([] { MetricExpression2d("pi/6", "0.01*(u", "1"); });
  EXPECT_NE(msg.find("h1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("0.01*(u"), std::string::npos) << msg;
  EXPECT_THROW(MetricExpression2d("alpha_undefined", "1", "1"), InputError);
  EXPECT_THROW(CSAnalytic2d(box2(0, 0, 1, 1), "0", "1", "sin("), InputError);
  const std::string msg3 = messageOf<InputError>([] { MetricExpression3d({"1", "2", "w"}); });
  EXPECT_NE(msg3.find("h3"), std::string::npos) << msg3;
  EXPECT_THROW(MetricExpression3d({"1", "1", "1"}, {"1", "0", "0"}, {"0", "1", "z+"}), InputError);
}

TEST(ControlAnalytic, NonPositiveOrNonFiniteLengthsThrowMeshingErrorNamingThePoint) {
  const CSAnalytic2d cs(box2(0, 0, 3, 1), "0", "0.01", "0.0101-0.005*u");  // h2 < 0 beyond u = 2.02
  EXPECT_NO_THROW(cs.getMetric(Vec2(2.0, 0.5)));
  const std::string msg = messageOf<MeshingError>([&] { cs.getMetric(Vec2(2.5, 0.25)); });
  EXPECT_NE(msg.find("h2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("2.5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("0.25"), std::string::npos) << msg;
  const MetricExpression2d nan("0", "sqrt(u-1)", "1");
  EXPECT_THROW(nan(Vec2(0.5, 0)), MeshingError);
  const MetricExpression2d badAngle("1/0", "1", "1");
  EXPECT_THROW(badAngle(Vec2(0, 0)), MeshingError);
  const MetricExpression3d zero({"x", "1", "1"});
  const std::string msg3 = messageOf<MeshingError>([&] { zero(Vec3(0, 0.75, 0)); });
  EXPECT_NE(msg3.find("0.75"), std::string::npos) << msg3;
}

TEST(ControlAnalytic, ExpressionsIn3dWithDirections) {
  const MetricExpression3d axes({"0.1", "0.2+x", "0.3"});
  const Metric3d a = axes(Vec3(0.5, 0, 0));
  EXPECT_NEAR(a.lengthAlong(Vec3(1, 0, 0)), 0.1, 1e-12);
  EXPECT_NEAR(a.lengthAlong(Vec3(0, 1, 0)), 0.7, 1e-12);
  EXPECT_NEAR(a.lengthAlong(Vec3(0, 0, 1)), 0.3, 1e-12);
  // e2 (here e1 + the true second direction) is made orthogonal to e1; e3 = e1 × e2.
  const MetricExpression3d rotated({"0.1", "0.2", "0.4"}, {"cos(z)", "sin(z)", "0"}, {"cos(z)-sin(z)", "sin(z)+cos(z)", "0"});
  const double z = 0.3;
  const Metric3d m = rotated(Vec3(0, 0, z));
  EXPECT_NEAR(m.lengthAlong(Vec3(std::cos(z), std::sin(z), 0)), 0.1, 1e-12);
  EXPECT_NEAR(m.lengthAlong(Vec3(-std::sin(z), std::cos(z), 0)), 0.2, 1e-12);
  EXPECT_NEAR(m.lengthAlong(Vec3(0, 0, 1)), 0.4, 1e-12);
  const MetricExpression3d parallel({"1", "1", "1"}, {"1", "0", "0"}, {"2", "0", "0"});
  EXPECT_THROW(parallel(Vec3::Zero()), MeshingError);
  const CSAnalytic3d cs(kCube, rotated);
  EXPECT_LT(metricDifference(cs.getMetric(Vec3(0.2, 0.2, z)), m), 1e-12);
}

TEST(ControlAnalytic, CallablesAndSubDomains) {
  CSAnalytic2d cs(box2(0, 0, 1, 1), [](const Vec2&) { return Metric2d::isotropic(0.1); });
  cs.addRegion(box2(0.5, 0.5, 1, 1), [](const Vec2&) { return Metric2d::isotropic(0.01); });
  cs.addRegion(box2(0.7, 0.7, 0.8, 0.8), [](const Vec2&) { return Metric2d::isotropic(0.001); });
  EXPECT_NEAR(cs.getMetric(Vec2(0.2, 0.2)).sizing.lengthAlong(Vec2(1, 0)), 0.1, 1e-12);
  EXPECT_NEAR(cs.getMetric(Vec2(0.6, 0.6)).sizing.lengthAlong(Vec2(1, 0)), 0.01, 1e-12);
  EXPECT_NEAR(cs.getMetric(Vec2(0.75, 0.75)).sizing.lengthAlong(Vec2(1, 0)), 0.001, 1e-12);
  EXPECT_THROW(CSAnalytic2d(box2(0, 0, 1, 1), CSAnalytic2d::MetricFunction{}), InputError);
  EXPECT_THROW(CSAnalytic2d(Box2(), [](const Vec2&) { return Metric2d(); }), InputError);
  CSAnalytic3d cs3(kCube, [](const Vec3&) { return Metric3d::isotropic(0.1); });
  Box3 sub;
  sub.add(Vec3(0.5, 0.5, 0.5));
  sub.add(Vec3(1, 1, 1));
  cs3.addRegion(sub, [](const Vec3&) { return Metric3d::isotropic(0.02); });
  EXPECT_NEAR(cs3.getMetric(Vec3(0.9, 0.9, 0.9)).lengthAlong(Vec3(1, 0, 0)), 0.02, 1e-12);
  EXPECT_NEAR(cs3.getMetric(Vec3(0.1, 0.9, 0.9)).lengthAlong(Vec3(1, 0, 0)), 0.1, 1e-12);
}

TEST(ControlAnalytic, SurfaceSuppliesTheParameterizationTensor) {
  auto sphere = std::make_shared<SphereSurface>(Frame(), 2.0);
  const CSAnalytic2d cs(box2(0, -1, kPi, 1), "0", "0.1", "0.1", sphere, 1e-8);
  const Vec2 p(0.4, 0.7);
  EXPECT_LT((cs.getMetric(p).parameterization - sphere->parameterizationTensor(p, 1e-8)).norm(), 1e-12);
  EXPECT_THROW(CSAnalytic2d(box2(0, 0, 1, 1), "0", "1", "1", sphere, -1), InputError);
}

TEST(ControlAnalytic, ConcurrentQueriesMatchSerialOnes) {
  auto sphere = std::make_shared<SphereSurface>(Frame(), 1.0);
  const CSAnalytic2d cs(box2(0, 0, 2, 1), "pi/6 + u*v", "0.01 + 0.02*sin(3*u)^2", "0.0101-0.005*u", sphere, 1e-8);
  const CSAnalytic3d cs3(kCube, MetricExpression3d({"0.1+x", "0.2+y*y", "0.3+z"}, {"1", "y", "0"}, {"0", "1", "x"}));
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0, 2), v(0, 1);
  std::vector<Vec2> pts(4000);
  std::vector<Vec3> pts3(4000);
  for (Vec2& p : pts) p = Vec2(u(rng), v(rng));
  for (Vec3& p : pts3) p = Vec3(v(rng), v(rng), v(rng));
  std::vector<Mat2> serial(pts.size()), parallel(pts.size());
  std::vector<Mat3> serial3(pts3.size()), parallel3(pts3.size());
  for (std::size_t i = 0; i < pts.size(); ++i) serial[i] = cs.getMetric(pts[i]).transformation();
  for (std::size_t i = 0; i < pts3.size(); ++i) serial3[i] = cs3.getMetric(pts3[i]).matrix();
  auto work = [&](std::size_t first) {
    for (int round = 0; round < 3; ++round)
      for (std::size_t i = first; i < pts.size(); i += 2) {
        parallel[i] = cs.getMetric(pts[i]).transformation();
        parallel3[i] = cs3.getMetric(pts3[i]).matrix();
      }
  };
  std::thread a(work, 0), b(work, 1);
  a.join();
  b.join();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    ASSERT_EQ(serial[i], parallel[i]) << i;
    ASSERT_EQ(serial3[i], parallel3[i]) << i;
  }
}

TEST(ControlAnalytic, ManyInstancesPerThreadStayIndependent) {
  // More instances than per-thread slots: evicted parsers are re-created correctly.
  std::vector<MetricExpression2d> exprs;
  for (int i = 0; i < 20; ++i) exprs.emplace_back("0", std::to_string(0.01 * (i + 1)), "1");
  for (int round = 0; round < 3; ++round)
    for (int i = 0; i < 20; ++i) EXPECT_NEAR(exprs[i](Vec2(0, 0)).lengthAlong(Vec2(1, 0)), 0.01 * (i + 1), 1e-12);
}

TEST(ControlAnalytic, IdentityIsEuclidean) {
  const CSIdentity2d id2(box2(0, 0, 1, 1));
  EXPECT_EQ(id2.getMetric(Vec2(0.3, 0.3)).transformation(), Mat2::Identity());
  const CSIdentity3d id3(kCube);
  EXPECT_EQ(id3.getMetric(Vec3(3, 3, 3)).matrix(), Mat3::Identity());
  EXPECT_EQ(id3.revision(), 0u);
}
