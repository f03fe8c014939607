#include <gtest/gtest.h>

#include <cmath>

#include "mesher/core/MeshOptions.h"

using namespace aniso;

TEST(MeshOptions, ThesisDefaultsAreValid) {
  SizingParameters s;
  EXPECT_EQ(s.check(), "");
  EXPECT_DOUBLE_EQ(s.anisotropy, 5.0);
  EXPECT_DOUBLE_EQ(s.gradation, 4.0);
  EXPECT_DOUBLE_EQ(s.curvatureRatio, 0.15);
  EXPECT_DOUBLE_EQ(s.contourAnisotropy, 2.0);
  EXPECT_DOUBLE_EQ(s.hmaxRel, 0.5);
  EXPECT_DOUBLE_EQ(s.hminRel, 1e-4);
}

TEST(MeshOptions, RejectsAbsurdValues) {
  SizingParameters s;
  s.size = 0.0;
  EXPECT_NE(s.check(), "");
  s.size = -1.0;
  EXPECT_NE(s.check(), "");
  s.size = std::nan("");
  EXPECT_NE(s.check(), "");
  s = SizingParameters{};
  s.hmin = 2.0;
  s.hmax = 1.0;
  EXPECT_NE(s.check(), "");
  s = SizingParameters{};
  s.gradation = 0.5;
  EXPECT_NE(s.check(), "");
  s = SizingParameters{};
  s.anisotropy = 0.9;
  EXPECT_NE(s.check(), "");
}

TEST(MeshOptions, SizesRelativeToModel) {
  SizingParameters s;
  EXPECT_DOUBLE_EQ(s.hmaxFor(10.0), 5.0);
  EXPECT_DOUBLE_EQ(s.hminFor(10.0), 1e-3);
  s.hmax = 2.0;
  EXPECT_DOUBLE_EQ(s.hmaxFor(10.0), 2.0);
  s.size = 0.5;
  EXPECT_DOUBLE_EQ(s.hmaxFor(10.0), 0.5);
  // Isotropic runs clamp the contour anisotropy to the global one (γ_ac ≤ γ_a).
  s.anisotropy = 1.0;
  EXPECT_EQ(s.check(), "");
  EXPECT_DOUBLE_EQ(s.contourAnisotropyEff(), 1.0);
}

TEST(MeshOptions, ProgramDefaultsAreGmshLike) {
  const SizingParameters s = SizingParameters::forAnalysis();
  EXPECT_EQ(s.check(), "");
  EXPECT_NEAR(s.curvatureRatio, 2 * std::acos(-1.0) / 12, 1e-15);
  EXPECT_NEAR(elementsPerCircleForCurvatureRatio(s.curvatureRatio), 12.0, 1e-12);
  EXPECT_TRUE(s.curvature);
  EXPECT_DOUBLE_EQ(s.hmaxRel, 0.1);  // Gmsh's default size
  EXPECT_DOUBLE_EQ(s.chordDeviationRel, 5e-4);  // chords within 0.05 % of the diagonal
  EXPECT_DOUBLE_EQ(SizingParameters{}.chordDeviationRel, 0.0);  // the thesis: elements per circle only
  // everything else is the thesis' table
  EXPECT_DOUBLE_EQ(s.anisotropy, SizingParameters{}.anisotropy);
  EXPECT_DOUBLE_EQ(s.hminRel, SizingParameters{}.hminRel);
}

TEST(MeshOptions, SizeIsTheLargestAndBoundsHmin) {
  SizingParameters s;
  s.size = 2.0;
  EXPECT_DOUBLE_EQ(s.hmaxFor(1000.0), 2.0);  // not the relative 500
  s.hmin = 3.0;
  EXPECT_NE(s.check(), "");  // --hmin above --size
  s.hmin = 0.5;
  EXPECT_EQ(s.check(), "");
  EXPECT_DOUBLE_EQ(s.hminFor(1000.0), 0.5);
}
