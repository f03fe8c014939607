// volumeChordDeviation (mesher/sizing/VolumeChordBound.h): the chord deviation bounded by
// the model's volume over its net convex curved area, on hand-made models of spheres.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "mesher/geometry/SphereSurface.h"
#include "mesher/sizing/VolumeChordBound.h"

using namespace aniso;

namespace {

constexpr double kPi = std::numbers::pi;

/// One face: a sphere of radius r about the origin.
int addSphereFace(Model& m, double r) {
  ModelFace f;
  f.surface = std::make_shared<SphereSurface>(Frame(), r);
  f.uvBounds.add(Vec2(0, -kPi / 2));
  f.uvBounds.add(Vec2(2 * kPi, kPi / 2));
  f.cadArea = 4 * kPi * r * r;
  m.faces.push_back(f);
  return static_cast<int>(m.faces.size()) - 1;
}

/// One shell of one face, the face used `reversed` (its normal into the shell).
int addShell(Model& m, int face, bool reversed) {
  ModelShell s;
  s.faces.push_back({face, reversed});
  s.closed = true;
  m.shells.push_back(s);
  return static_cast<int>(m.shells.size()) - 1;
}

/// A ball of radius r, or a hollow ball (a void of radius inner > 0).
Model ball(double r, double inner = 0) {
  Model m;
  ModelSolid solid;
  solid.outerShell = addShell(m, addSphereFace(m, r), false);
  solid.cadVolume = 4.0 / 3 * kPi * r * r * r;
  if (inner > 0) {
    solid.voidShells.push_back(addShell(m, addSphereFace(m, inner), true));
    solid.cadVolume -= 4.0 / 3 * kPi * inner * inner * inner;
  }
  m.solids.push_back(solid);
  return m;
}

}  // namespace

TEST(VolumeChordBound, ABallGetsItsVolumeOverItsArea) {
  // V / B = r / 3 for a ball
  const double r = 2;
  EXPECT_NEAR(volumeChordDeviation(ball(r), 1.0), kVolumeChordRatio * r / 3, 1e-9);
  // a bound above the model-wide deviation leaves it
  EXPECT_EQ(volumeChordDeviation(ball(r), 1e-6), 1e-6);
}

TEST(VolumeChordBound, AThinHollowBallIsBoundedByItsRadiusNotItsThickness) {
  // the void's sphere bulges into the solid: its chords add what the outer one's remove
  const double r = 2, inner = 1.98;
  const Model m = ball(r, inner);
  const double v = 4.0 / 3 * kPi * (r * r * r - inner * inner * inner), b = 4 * kPi * (r * r - inner * inner);
  EXPECT_NEAR(volumeChordDeviation(m, 1.0), std::min(1.0, kVolumeChordRatio * v / b), 1e-9);
  // bounded by the radius (V / B = r / 2 for a thin wall), not by the thickness (V / A)
  const double area = 4 * kPi * (r * r + inner * inner);
  EXPECT_GT(volumeChordDeviation(m, 1.0), 50 * kVolumeChordRatio * v / area);
}

TEST(VolumeChordBound, NothingKnownNothingBounded) {
  EXPECT_EQ(volumeChordDeviation(ball(1), 0.0), 0.0);  // the thesis' sizing: no chord bound
  Model m = ball(1);
  m.faces[0].cadArea = 0;  // area unknown
  EXPECT_EQ(volumeChordDeviation(m, 0.5), 0.5);
  m = ball(1);
  m.solids[0].cadVolume = 0;  // volume unknown
  EXPECT_EQ(volumeChordDeviation(m, 0.5), 0.5);
  EXPECT_EQ(volumeChordDeviation(Model{}, 0.5), 0.5);  // no solid
}
