// Tests of restrictToSurface (mesher/sizing/UserSizing.h): the 2D sizing a 3D source
// induces on a surface, including a nearly singular parametrisation.
#include <gtest/gtest.h>
#include <cmath>

#include "mesher/sizing/UserSizing.h"

using namespace aniso;

TEST(RestrictToSurface, PlaneKeepsTheSizes) {
  // the plane z = 0 with x = 2u, y = v and the parameterization tensor I: lengths of
  // (du, dv) are |(2 du, dv)| in space, measured in the isotropic 3D size 0.5
  const Metric2d m = restrictToSurface(Metric3d::isotropic(0.5), Vec3(2, 0, 0), Vec3(0, 1, 0), Mat2::Identity());
  const Mat2 t = m.matrix() * m.matrix();
  EXPECT_NEAR(t(0, 0), 16.0, 16.0 * 1e-9);  // (2 / 0.5)²
  EXPECT_NEAR(t(1, 1), 4.0, 4.0 * 1e-9);    // (1 / 0.5)²
  EXPECT_NEAR(t(0, 1), 0.0, 1e-12);
}

TEST(RestrictToSurface, NearlySingularParametrisationStaysDefinite) {
  // p_u of length 1e-9 (a pole): the tensor's eigenvalues 4e-18 and 4 were below rounding;
  // the floor keeps the metric positive definite, with the well-defined direction intact
  const Metric2d m = restrictToSurface(Metric3d::isotropic(0.5), Vec3(1e-9, 0, 0), Vec3(0, 1, 0), Mat2::Identity());
  const Mat2 t = m.matrix() * m.matrix();
  EXPECT_GT(t(0, 0), 0.0);
  EXPECT_NEAR(t(1, 1), 4.0, 4.0 * 1e-9);
  EXPECT_LE(t(1, 1) / t(0, 0), 1.0 / kRestrictedTensorFloor);
}

TEST(RestrictToSurface, NearlyParallelDerivativesDoNotThrow) {
  // p_u and p_v parallel to 1e-12 (a collapsed corner of the parameter square): the small
  // eigenvalue of the raw tensor rounds to <= 0
  const Vec3 pv(0.6, 0.8, 0);
  const Vec3 pu = 3.0 * pv + Vec3(0, 0, 1e-12);
  Metric2d m = Metric2d::isotropic(1);
  ASSERT_NO_THROW(m = restrictToSurface(Metric3d::isotropic(0.5), pu, pv, Mat2::Identity()));
  const Mat2 t = m.matrix() * m.matrix();
  EXPECT_GT(t.determinant(), 0.0);
}

TEST(UserSizingBounded, LengthsClampedDirectionsKept) {
  UserSizing u;
  u.global = Metric3d::isotropic(100.0);
  SizingSource s;
  s.metric = Metric3d::fromDirections(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), 0.01, 2.0, 50.0);
  u.sources.push_back(s);
  const UserSizing b = u.bounded(0.1, 10.0);
  EXPECT_NEAR(b.global->axes().lengths.maxCoeff(), 10.0, 1e-9);
  const MetricAxes<3> ax = b.sources[0].metric.axes();
  EXPECT_NEAR(ax.lengths(0), 0.1, 1e-12);
  EXPECT_NEAR(ax.lengths(1), 2.0, 1e-9);
  EXPECT_NEAR(ax.lengths(2), 10.0, 1e-9);
  EXPECT_NEAR(std::abs(ax.directions.col(0).x()), 1.0, 1e-9);  // the smallest size along x still
}
