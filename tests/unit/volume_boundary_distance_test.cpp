// Tests of the closest surface point (mesher/volume/BoundaryDistance.h) and of M_v graded from
// the surface with it (VolumeMetricSpace with a surface, VolumeControlSpace.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <random>
#include <vector>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/volume/BoundaryDistance.h"
#include "mesher/volume/VolumeControlSpace.h"

using namespace aniso;

namespace {

// The unit cube's surface, n × n squares a face, two triangles a square.
void cubeSurface(int n, std::vector<Vec3>& points, std::vector<std::array<int, 3>>& triangles) {
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int base = static_cast<int>(points.size());
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          Vec3 p;
          p[axis] = side;
          p[(axis + 1) % 3] = static_cast<double>(i) / n;
          p[(axis + 2) % 3] = static_cast<double>(j) / n;
          points.push_back(p);
        }
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const int a = base + i * (n + 1) + j, b = a + n + 1;
          triangles.push_back({a, b, b + 1});
          triangles.push_back({a, b + 1, a + 1});
        }
    }
}

Box3 box() {
  Box3 b;
  b.add(Vec3(-1, -1, -1));
  b.add(Vec3(2, 2, 2));
  return b;
}

}  // namespace

TEST(BoundaryDistance, ClosestPointOnTriangleInEachRegion) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  EXPECT_EQ(closestPointOnTriangle(Vec3(-1, -1, 3), a, b, c), a);                            // vertex a
  EXPECT_EQ(closestPointOnTriangle(Vec3(3, -1, 1), a, b, c), b);                             // vertex b
  EXPECT_EQ(closestPointOnTriangle(c, a, b, c), c);                                          // on a vertex
  EXPECT_LT((closestPointOnTriangle(Vec3(1, -2, 1), a, b, c) - Vec3(1, 0, 0)).norm(), 1e-15);  // edge ab
  EXPECT_LT((closestPointOnTriangle(Vec3(2, 2, -1), a, b, c) - Vec3(1, 1, 0)).norm(), 1e-15);  // edge bc
  EXPECT_LT((closestPointOnTriangle(Vec3(0.5, 0.5, 4), a, b, c) - Vec3(0.5, 0.5, 0)).norm(), 1e-15);  // face
}

TEST(BoundaryDistance, TreeFindsTheClosestPointWithinTheRadius) {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  cubeSurface(7, points, triangles);
  const TriangleTree tree(points, triangles);
  EXPECT_EQ(tree.size(), triangles.size());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  for (int k = 0; k < 300; ++k) {
    const Vec3 x(u(rng), u(rng), u(rng));
    double best = 1e300;
    for (const auto& t : triangles)
      best = std::min(best, (closestPointOnTriangle(x, points[t[0]], points[t[1]], points[t[2]]) - x).norm());
    Vec3 c;
    ASSERT_TRUE(tree.closest(x, 10.0, c));
    EXPECT_NEAR((c - x).norm(), best, 1e-12);
    EXPECT_EQ(tree.closest(x, 0.999 * best, c), false);
  }
  const TriangleTree empty(points, {});
  Vec3 c;
  EXPECT_FALSE(empty.closest(Vec3(0.5, 0.5, 0.5), 10.0, c));
}

TEST(BoundaryDistance, NearGridAnswersOnlyForCertainlyFarPoints) {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  cubeSurface(7, points, triangles);
  const double radius = 0.1;
  const TriangleTree tree(points, triangles, radius);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  int far = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 x(u(rng), u(rng), u(rng));
    Vec3 c;
    for (const double d : {0.05, radius}) {
      // beyond() is a certificate: never true for a point within d of a triangle.
      if (tree.beyond(x, d)) {
        ++far;
        EXPECT_FALSE(tree.closest(x, d, c)) << x.transpose();
      }
    }
    EXPECT_FALSE(tree.beyond(x, 2 * radius));  // beyond the grid's radius: unknown
  }
  EXPECT_GT(far, 1000);  // most of the box is far from the cube's surface: the grid answers
  for (const Vec3& p : points) EXPECT_FALSE(tree.beyond(p, 0.0));  // surface points: never far
  EXPECT_FALSE(TriangleTree(points, triangles).beyond(Vec3(0.5, 0.5, 0.5), 0.01));  // no grid
}

TEST(BoundaryDistance, VolumeMetricGradesFromTheSurface) {
  // h = 0.1 everywhere, f = 1.4: M on the surface, M / f from one unit length of M (0.1) on.
  const double h = 0.1, f = kVolumeLengthFactor;
  const auto user = std::make_shared<CSAnalytic3d>(box(), [h](const Vec3&) { return Metric3d::isotropic(h); });
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  cubeSurface(10, points, triangles);
  const VolumeMetricSpace mv(user, points, f, std::make_shared<TriangleTree>(points, triangles));
  const double t = kVolumeTransitionLayers * h;
  EXPECT_EQ(mv.lengthFactorAt(Vec3(0.3, 0.4, 0.0)), 1.0);   // a surface node
  EXPECT_EQ(mv.lengthFactorAt(Vec3(0.33, 0.47, 1.0)), 1.0);  // on a face, not a node
  EXPECT_NEAR(mv.lengthFactorAt(Vec3(0.5, 0.5, 0.25 * t)), 1 + 0.25 * (f - 1), 1e-12);
  EXPECT_NEAR(mv.lengthFactorAt(Vec3(0.5, 1 - 0.5 * t, 0.5)), 1 + 0.5 * (f - 1), 1e-12);
  EXPECT_EQ(mv.lengthFactorAt(Vec3(0.5, 0.5, 1.01 * t)), f);
  EXPECT_EQ(mv.lengthFactorAt(Vec3(0.5, 0.5, 0.5)), f);
  // The metric is M over that factor.
  const Vec3 x(0.4, 0.6, 0.5 * t), d(1, 2, -3);
  EXPECT_NEAR(mv.getMetric(x).length(d) * mv.lengthFactorAt(x), user->getMetric(x).length(d), 1e-12);
  // Without a surface: the step of before (M at the nodes, M / f elsewhere).
  const VolumeMetricSpace step(user, points, f);
  EXPECT_EQ(step.lengthFactorAt(Vec3(0.5, 0.5, 0.25 * t)), f);
  EXPECT_EQ(step.lengthFactorAt(Vec3(0.3, 0.4, 0.0)), 1.0);
}

// lengthFactorFrom (the factor from the held M_v, no query of M) equals lengthFactorAt to
// rounding, near and far from the surface, with an isotropic graded metric (a near grid at
// the metric's largest size, as the volume mesher builds it) and an anisotropic one.
TEST(BoundaryDistance, LengthFactorFromHeldTensorEqualsQueried) {
  std::vector<Vec3> points;
  std::vector<std::array<int, 3>> triangles;
  cubeSurface(10, points, triangles);
  const auto graded = std::make_shared<CSAnalytic3d>(
      box(), [](const Vec3& x) { return Metric3d::isotropic(0.05 + 0.05 * std::clamp(x.x(), 0.0, 1.0)); });
  const auto aniso = std::make_shared<CSAnalytic3d>(box(), [](const Vec3&) {
    return Metric3d::fromDirections(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), 0.1, 0.06, 0.03);
  });
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const auto& user : {std::shared_ptr<const ControlSpace3d>(graded), std::shared_ptr<const ControlSpace3d>(aniso)}) {
    const VolumeMetricSpace mv(user, points, kVolumeLengthFactor,
                               std::make_shared<TriangleTree>(points, triangles, 0.1));
    int near = 0;
    for (int k = 0; k < 3000; ++k) {
      Vec3 x(u(rng), u(rng), u(rng));
      if (k % 3 == 0) x.z() = 0.2 * x.z() * x.z();  // many near the face z = 0
      const double at = mv.lengthFactorAt(x), from = mv.lengthFactorFrom(x, mv.getMetric(x).matrix());
      EXPECT_NEAR(from, at, 1e-9 * at) << x.transpose();
      near += at < kVolumeLengthFactor;
    }
    EXPECT_GT(near, 300);  // the graded layer is exercised
    for (const Vec3& p : points) EXPECT_EQ(mv.lengthFactorFrom(p, mv.getMetric(p).matrix()), 1.0);
  }
}

