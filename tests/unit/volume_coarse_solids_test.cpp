// Tests of coarseSolidSources (mesher/volume/CoarseSolids.h): the box source asked for a
// solid whose tets stay below the mean-ratio bar.
#include <gtest/gtest.h>

#include "mesher/volume/CoarseSolids.h"
#include "volume_refine_fixture.h"

using namespace aniso;
using namespace aniso::testing;

TEST(CoarseSolids, OneBoxSourcePerSolidBelowTheBar) {
  std::set<Triple> boundary;
  const SolidTetMesh s = cubeSolid(2, boundary);  // 8 triangles per face: coarse
  const CubeSurface c = cubeSurface(s, boundary);
  double length = 0;
  std::size_t edges = 0;
  for (const auto& t : c.surface.triangles)
    for (int k = 0; k < 3; ++k, ++edges) length += (c.surface.nodes[t[(k + 1) % 3]] - c.surface.nodes[t[k]]).norm();
  length /= static_cast<double>(edges);

  std::vector<SolidOutcome> solids(1);
  solids[0].quality.meanRatio.add(0.70);
  solids[0].quality.meanRatio.add(0.80);  // mean 0.75: coarse
  const std::vector<SizingSource> src = coarseSolidSources(c.model, c.surface, solids);
  ASSERT_EQ(src.size(), 1u);
  EXPECT_EQ(src[0].kind, SizingSource::Kind::Box);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(src[0].a[i], -length, 1e-12);
    EXPECT_NEAR(src[0].b[i], 1.0 + length, 1e-12);
  }
  // isotropic, size kCoarseRefine times the mean boundary edge (M = I / h)
  EXPECT_NEAR(src[0].metric.matrix()(0, 0), 1.0 / (kCoarseRefine * length), 1e-9);
  EXPECT_NEAR(src[0].metric.matrix()(1, 1), src[0].metric.matrix()(0, 0), 1e-12);
  EXPECT_NEAR(src[0].metric.matrix()(0, 1), 0.0, 1e-12);
  EXPECT_TRUE(src[0].contains(Vec3(0.5, 0.5, 0.5)));

  solids[0].quality.meanRatio.add(0.95);
  solids[0].quality.meanRatio.add(0.95);  // mean 0.85: not coarse
  EXPECT_TRUE(coarseSolidSources(c.model, c.surface, solids).empty());
  // a solid meshed finely (more than kCoarseTrianglesPerFace triangles per face) is not
  // coarse, whatever its quality
  {
    std::set<Triple> fineBoundary;
    const SolidTetMesh fine = cubeSolid(6, fineBoundary);
    const CubeSurface cf = cubeSurface(fine, fineBoundary);
    ASSERT_GT(cf.surface.triangles.size(), 6 * kCoarseTrianglesPerFace);
    std::vector<SolidOutcome> poor(1);
    poor[0].quality.meanRatio.add(0.5);
    EXPECT_TRUE(coarseSolidSources(cf.model, cf.surface, poor).empty());
  }
  solids[0] = SolidOutcome{};
  solids[0].status = SolidOutcome::Status::Failed;  // a failed solid is not asked for
  solids[0].quality.meanRatio.add(0.5);
  EXPECT_TRUE(coarseSolidSources(c.model, c.surface, solids).empty());
}
