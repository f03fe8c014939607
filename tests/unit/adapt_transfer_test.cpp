// Tests of the field transfer of `adapt --transfer` (mesher/adapt/CellLocator, FieldTransfer):
// on perturbed tet and triangle meshes of the unit cube / square, a linear field is carried
// to points inside exactly, each point is found in a cell that contains it, points outside
// get the value at their closest point of the mesh (the box's clamp), and the result does
// not depend on how often it is asked.
#include <gtest/gtest.h>

#include <random>

#include "mesher/adapt/CellLocator.h"
#include "mesher/adapt/FieldTransfer.h"
#include "mesher/core/Error.h"
#include "tests/unit/adapt_fixtures.h"

namespace aniso {
namespace {

/// Two components: a linear field and another.
std::vector<double> linear(const std::vector<Vec3>& pts) {
  std::vector<double> v;
  for (const Vec3& p : pts) v.insert(v.end(), {1 + 2 * p.x() - 3 * p.y() + 0.5 * p.z(), -p.x() + 4 * p.z()});
  return v;
}

std::vector<Vec3> randomPoints(int n, double lo, double hi, unsigned seed, bool flat) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) {
    Vec3 p(u(rng), u(rng), u(rng));
    if (flat) p.z() = 0.3 * p.x() + 0.1 * p.y();  // the plane of randomMesh(2, ...)
    out.push_back(p);
  }
  return out;
}

TEST(AdaptTransfer, LinearFieldIsExactInsideATetMesh) {
  const PatchMesh m = randomMesh(3, 7, 3);
  const std::vector<Vec3> pts = randomPoints(500, 0, 1, 11, false);
  const TransferredField t = transferField(m, linear(m.nodes), 2, pts);
  const std::vector<double> exact = linear(pts);
  ASSERT_EQ(t.values.size(), exact.size());
  for (std::size_t i = 0; i < exact.size(); ++i) EXPECT_NEAR(t.values[i], exact[i], 1e-12) << i;
  EXPECT_EQ(t.outside, 0u);
  // the cell found contains the point
  const CellLocator loc(m);
  for (const Vec3& p : pts) {
    const CellHit h = loc.locate(p);
    Vec3 back = Vec3::Zero();
    for (int k = 0; k < 4; ++k) back += h.bary[k] * m.nodes[m.conn[m.offsets[h.cell] + k]];
    EXPECT_LT((back - p).norm(), 1e-12);
    EXPECT_EQ(h.distance, 0.0);
  }
}

TEST(AdaptTransfer, LinearFieldIsExactOnATriangleSurface) {
  const PatchMesh m = randomMesh(2, 9, 5);
  const std::vector<Vec3> pts = randomPoints(300, 0, 1, 13, true);
  const TransferredField t = transferField(m, linear(m.nodes), 2, pts);
  const std::vector<double> exact = linear(pts);
  for (std::size_t i = 0; i < exact.size(); ++i) EXPECT_NEAR(t.values[i], exact[i], 1e-12) << i;
}

TEST(AdaptTransfer, PointsOutsideTakeTheValueAtTheirClosestPoint) {
  const PatchMesh m = randomMesh(3, 5, 9);  // boundary nodes unperturbed: the mesh is the unit cube
  const std::vector<Vec3> pts = randomPoints(200, -0.2, 1.2, 17, false);
  const TransferredField t = transferField(m, linear(m.nodes), 2, pts);
  std::vector<Vec3> feet;
  std::size_t outside = 0;
  double far = 0;
  for (const Vec3& p : pts) {
    const Vec3 q = p.cwiseMax(Vec3::Zero()).cwiseMin(Vec3::Ones());
    feet.push_back(q);
    outside += (q - p).norm() > 0;
    far = std::max(far, (q - p).norm());
  }
  const std::vector<double> exact = linear(feet);
  for (std::size_t i = 0; i < exact.size(); ++i) EXPECT_NEAR(t.values[i], exact[i], 1e-12) << i;
  EXPECT_EQ(t.outside, outside);
  EXPECT_NEAR(t.maxDistance, far, 1e-12);
}

TEST(AdaptTransfer, DeterministicAndChecked) {
  const PatchMesh m = randomMesh(3, 4, 1);
  const std::vector<Vec3> pts = randomPoints(100, -0.1, 1.1, 2, false);
  EXPECT_EQ(transferField(m, linear(m.nodes), 2, pts).values, transferField(m, linear(m.nodes), 2, pts).values);
  EXPECT_THROW(transferField(m, linear(m.nodes), 3, pts), MeshingError);
  EXPECT_THROW(transferField(PatchMesh{}, {}, 1, pts), MeshingError);
}

}  // namespace
}  // namespace aniso
