// Unit tests of the 3D kernel's insertion-order helpers: Hilbert curve, BRIO, and the
// walk-seeding octree.
#include <gtest/gtest.h>

#include <cmath>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

#include "mesher/delaunay3d/Delaunay3d.h"
#include "mesher/delaunay3d/EnclosingBox.h"
#include "mesher/delaunay3d/Inserter.h"
#include "mesher/delaunay3d/SeedOctree.h"
#include "mesher/delaunay3d/SpatialSort.h"
#include "mesher/delaunay3d/Validate.h"

using namespace aniso;
using namespace aniso::del3d;

namespace {

std::vector<Vec3> randomPoints(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-2.0, 3.0);
  std::vector<Vec3> pts(n);
  for (Vec3& p : pts) p = Vec3(u(rng), u(rng), u(rng));
  return pts;
}

bool isPermutation(std::vector<std::uint32_t> order, std::size_t n) {
  std::sort(order.begin(), order.end());
  for (std::size_t k = 0; k < n; ++k)
    if (order.size() != n || order[k] != k) return false;
  return true;
}

}  // namespace

TEST(Delaunay3dSort, HilbertCurveVisitsNeighbouringCells) {
  const int bits = 3, n = 1 << bits;
  std::vector<std::array<int, 3>> cellAt(n * n * n, {-1, -1, -1});
  for (int x = 0; x < n; ++x)
    for (int y = 0; y < n; ++y)
      for (int z = 0; z < n; ++z) {
        const std::uint64_t h = hilbertIndex(x, y, z, bits);
        ASSERT_LT(h, static_cast<std::uint64_t>(n * n * n));
        ASSERT_EQ(cellAt[h][0], -1) << "index used twice";
        cellAt[h] = {x, y, z};
      }
  for (std::size_t h = 1; h < cellAt.size(); ++h) {
    const int d = std::abs(cellAt[h][0] - cellAt[h - 1][0]) + std::abs(cellAt[h][1] - cellAt[h - 1][1]) +
                  std::abs(cellAt[h][2] - cellAt[h - 1][2]);
    EXPECT_EQ(d, 1) << "at " << h;
  }
}

TEST(Delaunay3dSort, HilbertStateMachineEqualsSkillingsLoop) {
  std::mt19937_64 rng(7);
  for (int bits = 1; bits <= 21; ++bits) {
    const std::uint32_t top = (1u << bits) - 1;
    const std::uint32_t corners[2] = {0, top};
    for (const std::uint32_t x : corners)
      for (const std::uint32_t y : corners)
        for (const std::uint32_t z : corners) EXPECT_EQ(hilbertIndex(x, y, z, bits), hilbertIndexReference(x, y, z, bits));
    for (int k = 0; k < 20000; ++k) {
      const std::uint32_t x = static_cast<std::uint32_t>(rng()) & top, y = static_cast<std::uint32_t>(rng()) & top,
                          z = static_cast<std::uint32_t>(rng()) & top;
      ASSERT_EQ(hilbertIndex(x, y, z, bits), hilbertIndexReference(x, y, z, bits)) << bits << " " << x << " " << y << " " << z;
    }
  }
}

TEST(Delaunay3dSort, HilbertAndBrioOrdersArePermutations) {
  const std::vector<Vec3> pts = randomPoints(10000, 1);
  const auto h = hilbertOrder(pts);
  EXPECT_TRUE(isPermutation(h, pts.size()));
  // Hilbert order is local: consecutive points are much closer than random pairs.
  double along = 0;
  for (std::size_t k = 1; k < h.size(); ++k) along += (pts[h[k]] - pts[h[k - 1]]).norm();
  double random = 0;
  for (std::size_t k = 1; k < pts.size(); ++k) random += (pts[k] - pts[k - 1]).norm();
  EXPECT_LT(along, 0.1 * random);
  const auto b = brioOrder(pts, 7);
  EXPECT_TRUE(isPermutation(b, pts.size()));
  EXPECT_EQ(b, brioOrder(pts, 7));  // deterministic
  EXPECT_NE(b, brioOrder(pts, 8));
  // The last round (3/4 of the points) is Hilbert sorted.
  const std::size_t lastBegin = pts.size() / 4;
  double lastAlong = 0;
  for (std::size_t k = lastBegin + 1; k < b.size(); ++k) lastAlong += (pts[b[k]] - pts[b[k - 1]]).norm();
  EXPECT_LT(lastAlong, 0.15 * random);
  EXPECT_TRUE(hilbertOrder(std::vector<Vec3>{}).empty());
  EXPECT_TRUE(isPermutation(brioOrder(std::vector<Vec3>(5, Vec3(1, 1, 1))), 5));
}

TEST(Delaunay3dSort, LargeHilbertOrderKeepsTiesInIndexOrderAndNonFiniteLast) {
  // Above the radix threshold: equal keys (repeated points) in increasing index order,
  // non-finite points last in index order, as the pair sort of smaller inputs does.
  std::vector<Vec3> pts = randomPoints(6000, 3);
  for (std::size_t k = 0; k < 300; ++k) pts.push_back(pts[(k * 37) % 6000]);
  for (int k = 0; k < 7; ++k) pts.insert(pts.begin() + 1000 * k, Vec3(std::nan(""), 0, 0));
  const auto h = hilbertOrder(pts);
  ASSERT_TRUE(isPermutation(h, pts.size()));
  std::vector<std::size_t> position(pts.size());
  for (std::size_t k = 0; k < h.size(); ++k) position[h[k]] = k;
  for (std::size_t k = 0; k < 7; ++k) EXPECT_EQ(h[pts.size() - 7 + k], 1000 * k);
  for (std::size_t a = 0; a < pts.size(); ++a) {
    if (!pts[a].allFinite()) continue;
    for (std::size_t b = a + 1; b < pts.size(); ++b) {
      if (pts[b] == pts[a]) {
        EXPECT_LT(position[a], position[b]);
      }
    }
  }
  double along = 0, random = 0;
  for (std::size_t k = 1; k + 7 < h.size(); ++k) along += (pts[h[k]] - pts[h[k - 1]]).norm();
  const std::vector<Vec3> plain = randomPoints(6000, 3);
  for (std::size_t k = 1; k < plain.size(); ++k) random += (plain[k] - plain[k - 1]).norm();
  EXPECT_LT(along, 0.1 * random);
}

TEST(Delaunay3dSort, SeedOctreeShortensUnsortedWalks) {
  const std::vector<Vec3> pts = randomPoints(20000, 2);
  Box3 bounds;
  for (const Vec3& p : pts) bounds.add(p);
  std::uint64_t stepsPlain = 0, stepsSeeded = 0;
  {
    TetMesh mesh;
    createEnclosingBox(mesh, bounds);
    Inserter ins(mesh);
    for (const Vec3& p : pts) stepsPlain += ins.insert(p).walkSteps;
  }
  TetMesh mesh;
  const EnclosingBox eb = createEnclosingBox(mesh, bounds);
  SeedOctree octree(eb.box, 64);
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k) octree.update(mesh, TetId(k));
  Inserter ins(mesh);
  for (const Vec3& p : pts) {
    const TetId seed = octree.seed(mesh, p);
    ASSERT_TRUE(mesh.isAlive(seed));
    const InsertResult r = ins.insert(p, seed);
    ASSERT_EQ(r.status, InsertStatus::Inserted);
    stepsSeeded += r.walkSteps;
    for (const TetId t : ins.newTets()) octree.update(mesh, t);
  }
  EXPECT_GT(octree.numLeaves(), 100u);
  EXPECT_LT(stepsSeeded * 3, stepsPlain);
  EXPECT_TRUE(validate(mesh).empty());
  // The option of buildDelaunay gives the same (unique, random points) triangulation.
  TetMesh viaBuild;
  DelaunayOptions opt;
  opt.spatialSort = false;
  opt.useSeedOctree = true;
  const DelaunayResult r = buildDelaunay(viaBuild, pts, opt);
  EXPECT_EQ(r.inserted, pts.size());
  EXPECT_EQ(viaBuild.numTets(), mesh.numTets());
  ValidateOptions d;
  d.checkDelaunay = true;
  EXPECT_TRUE(validate(viaBuild, d).empty());
}
