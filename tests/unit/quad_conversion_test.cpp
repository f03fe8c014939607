// The whole per-face conversion (QuadConversion.h): all-quad on even planar domains, valid,
// boundary unchanged, deterministic.
#include <gtest/gtest.h>

#include "mesher/quad/QuadConversion.h"
#include "quad_fixtures.h"

namespace {

using namespace aniso;
using namespace aniso::quad;

struct Case {
  std::vector<facetest::Polygon> loops;
  double h;
};

void checkConversion(const Case& c, double minFraction) {
  FaceMesh fm = quadtest::triangleMesh(c.loops, c.h);
  const QuadMesh2d before = QuadMesh2d::fromFaceMesh(fm);
  const auto snap = quadtest::snapshot(before);
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of(c.loops), c.h);
  const QuadStats st = convertToQuads(fm, *cs);
  const QuadMesh2d after = QuadMesh2d::fromFaceMesh(fm);
  quadtest::expectValid(after, snap);
  const double fraction = static_cast<double>(fm.quads.size()) / (fm.quads.size() + fm.triangles.size());
  EXPECT_GE(fraction, minFraction) << "quads " << fm.quads.size() << " triangles " << fm.triangles.size()
                                   << " merge left " << st.merge.triangles << " paired " << st.paired;
  EXPECT_GT(st.jacobian.min(), 0.2);
  EXPECT_NEAR(st.mu.mean(), 1.0, 0.15);
}

TEST(QuadConversion, Square) { checkConversion({{facetest::rectangle(0, 0, 1, 1)}, 0.05}, 0.98); }

TEST(QuadConversion, PlateWithHole) {
  checkConversion({{facetest::rectangle(0, 0, 2, 1), facetest::circle(Vec2(0.7, 0.5), 0.25, 40, true)}, 0.04}, 0.98);
}

TEST(QuadConversion, Deterministic) {
  const std::vector<facetest::Polygon> loops{facetest::rectangle(0, 0, 2, 1), facetest::circle(Vec2(1, 0.5), 0.3, 30, true)};
  FaceMesh a = quadtest::triangleMesh(loops, 0.05), b = a;
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of(loops), 0.05);
  convertToQuads(a, *cs);
  convertToQuads(b, *cs);
  EXPECT_EQ(a.quads, b.quads);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.uv, b.uv);
}

}  // namespace
