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
