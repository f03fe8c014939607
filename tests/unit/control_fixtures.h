#pragma once
// Shared fixtures of the control-space tests (control_*_test.cpp): boxes, the two smooth
// test fields, and the checks every control space of a kind must pass (the proximity
// query cache; random point sources keeping the structure valid).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "mesher/control/MetricQueryCache.h"
#include "mesher/core/Types.h"
#include "mesher/metric/Metric.h"

namespace aniso::testing {

constexpr double kPi = std::numbers::pi;

inline Box2 box2(double u0, double v0, double u1, double v1) {
  Box2 b;
  b.add(Vec2(u0, v0));
  b.add(Vec2(u1, v1));
  return b;
}

inline Box3 box3(const Vec3& lo, const Vec3& hi) {
  Box3 b;
  b.add(lo);
  b.add(hi);
  return b;
}

inline const Box2 kSquare = box2(0, 0, 1, 1);
inline const Box3 kCube = box3(Vec3::Zero(), Vec3::Ones());

/// A rotating, strongly varying (smooth on [0,1]²) field used to force refinement.
inline Metric2d swirl(const Vec2& p) {
  const Vec2 d = p - Vec2(0.5, -0.2);
  const double r2 = (p - Vec2(0.5, 0.5)).squaredNorm();
  const double h1 = 0.004 + 0.2 * r2;
  return Metric2d::fromAngle(std::atan2(d.y(), d.x()), h1, 3 * h1);
}

/// A smooth field whose directions turn and whose lengths grow away from (0.5, 0.5, 0.5).
inline Metric3d twist(const Vec3& p) {
  const double r2 = (p - Vec3(0.5, 0.5, 0.5)).squaredNorm();
  const double h = 0.01 + 0.3 * r2;
  const double a = 1.5 * p.z();
  const Vec3 e1(std::cos(a), std::sin(a), 0), e2(-std::sin(a), std::cos(a), 0);
  return Metric3d::fromDirections(e1, e2, Vec3::UnitZ(), h, 2 * h, 3 * h);
}

/// The proximity cache of sec. 3.2.4 in front of a 3D control space: a query a hundredth
/// of the local size away is a hit, one two sizes away a miss.
template <class CS>
void expectQueryCache3d(const CS& cs) {
  MetricQueryCache3d cache(0.05);
  const Vec3 p(0.2, 0.3, 0.4);
  cache.get(cs, p);
  const double h = cs.getMetric(p).axes().lengths(0);
  cache.get(cs, p + Vec3(0.01 * h, 0, 0));
  cache.get(cs, p + Vec3(2 * h, 0, 0));
  EXPECT_EQ(cache.hits(), 1u);
  EXPECT_EQ(cache.misses(), 2u);
}

/// 60 random anisotropic point sources in [u0,u1]×[v0,v1] while the control space is
/// fresh, then initialization, then 60 more as updates; validate() after every insertion.
template <class CS>
void insertRandomSources2d(CS& cs, std::mt19937& rng, double u0, double u1, double v0, double v1) {
  std::uniform_real_distribution<double> u(u0, u1), v(v0, v1), h(-4, -1), a(0, kPi);
  for (int i = 0; i < 60; ++i) {
    const double h1 = std::pow(10, h(rng));
    cs.insertDiscreteSource(Vec2(u(rng), v(rng)), Metric2d::fromAngle(a(rng), h1, 4 * h1));
    ASSERT_NO_THROW(cs.validate()) << "after fresh insertion " << i;
  }
  cs.initializeControlVertices();
  cs.validate();
  for (int i = 0; i < 60; ++i) {
    const double h1 = std::pow(10, h(rng));
    cs.insertDiscreteSource(Vec2(u(rng), v(rng)), Metric2d::fromAngle(a(rng), h1, 4 * h1));
    ASSERT_NO_THROW(cs.validate()) << "after update insertion " << i;
  }
}

}  // namespace aniso::testing
