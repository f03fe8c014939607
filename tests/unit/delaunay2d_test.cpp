// Tests of the 2D triangulation kernel: construction, Bowyer–Watson insertion (identity and
// anisotropic metrics, degenerate inputs, constraints), validated after every operator.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/delaunay/Delaunay2d.h"
#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/PlaneTransform.h"
#include "mesher/delaunay/PointLocation.h"
#include "mesher/delaunay/SpatialSort.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/delaunay/Validate2d.h"
#include "delaunay2d_fixtures.h"

using namespace aniso;
using namespace aniso::del2d;
using namespace aniso::del2d::testing;

namespace {

/// Sorted vertex triples of the live triangles.
std::set<std::array<std::uint32_t, 3>> triangleSet(const Triangulation2d& tri) {
  std::set<std::array<std::uint32_t, 3>> s;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    if (!tri.isAlive(TriId(k))) continue;
    std::array<std::uint32_t, 3> v{tri.vertex(TriId(k), 0).index, tri.vertex(TriId(k), 1).index,
                                   tri.vertex(TriId(k), 2).index};
    std::sort(v.begin(), v.end());
    s.insert(v);
  }
  return s;
}

Mat2 stretched(double angle, double h1, double h2) {
  const Eigen::Rotation2Dd r(angle);
  return r.toRotationMatrix() * Eigen::Vector2d(1 / h1, 1 / h2).asDiagonal() * r.toRotationMatrix().transpose();
}

}  // namespace

TEST(Triangulation2d, InitialTwoTriangles) {
  Triangulation2d tri(unitBox());
  EXPECT_EQ(tri.numVertices(), 4u);
  EXPECT_EQ(tri.numTriangles(), 2u);
  EXPECT_VALID(tri, delaunayCheck());
  EXPECT_LT(tri.box().lo.x(), 0.0);
  EXPECT_GT(tri.box().hi.y(), 1.0);
  // Degenerate bounds (a single point) still give a box with area.
  Box2 single;
  single.add(Vec2(5, 5));
  Triangulation2d t2(single);
  EXPECT_GT(t2.box().size().minCoeff(), 0.0);
  EXPECT_VALID(t2, delaunayCheck());
  EXPECT_THROW(Triangulation2d(Box2{}), MeshingError);
}

TEST(Triangulation2d, RandomPointsValidAfterEveryInsertion) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Triangulation2d tri(unitBox());
  for (int k = 0; k < 300; ++k) {
    const InsertResult r = insertPoint(tri, Vec2(u(rng), u(rng)));
    ASSERT_EQ(r.status, InsertStatus::Inserted);
    EXPECT_EQ(r.created, r.cavitySize + 2);
    const auto problems = validate(tri, delaunayCheck());
    ASSERT_TRUE(problems.empty()) << "after point " << k << ":\n" << joined(problems);
  }
  EXPECT_EQ(tri.numVertices(), 304u);
  EXPECT_EQ(tri.numTriangles(), 2u * 300 + 2);  // T = 2V − h − 2 with the 4 corners on the hull
}

TEST(Triangulation2d, HundredThousandRandomPoints) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(-3.0, 7.0);
  std::vector<Vec2> pts(100000);
  for (Vec2& p : pts) p = Vec2(u(rng), u(rng));
  for (WalkStart ws : {WalkStart::LastTriangle, WalkStart::SeedQuadtree}) {
    TriangulateOptions opt;
    opt.walkStart = ws;
    TriangulateResult res;
    const Triangulation2d tri = triangulatePoints(pts, opt, &res);
    EXPECT_EQ(res.inserted, pts.size());
    EXPECT_EQ(tri.numTriangles(), 2 * pts.size() + 2);
    EXPECT_VALID(tri, delaunayCheck());
    EXPECT_LT(static_cast<double>(res.walkSteps) / pts.size(), 20.0);
  }
}

TEST(Triangulation2d, RegularGridManyCocircular) {
  std::vector<Vec2> pts;
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j) pts.emplace_back(i, j);
  for (bool sorted : {true, false}) {
    TriangulateOptions opt;
    opt.spatialSort = sorted;
    TriangulateResult res;
    const Triangulation2d tri = triangulatePoints(pts, opt, &res);
    EXPECT_EQ(res.inserted, pts.size());
    EXPECT_EQ(tri.numTriangles(), 2 * pts.size() + 2);
    EXPECT_VALID(tri, delaunayCheck());
  }
  // Small grid with validation after every insertion, in random order.
  std::vector<Vec2> small;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) small.emplace_back(0.5 * i, 0.5 * j);
  std::shuffle(small.begin(), small.end(), std::mt19937_64(3));
  Box2 b;
  for (const Vec2& p : small) b.add(p);
  Triangulation2d tri(b);
  for (const Vec2& p : small) {
    ASSERT_EQ(insertPoint(tri, p).status, InsertStatus::Inserted);
    ASSERT_TRUE(validate(tri, delaunayCheck()).empty());
  }
}

TEST(Triangulation2d, CollinearPoints) {
  Box2 b;
  b.add(Vec2(0, 0));
  b.add(Vec2(1, 1));
  Triangulation2d tri(b);
  std::vector<double> ts(200);
  for (int k = 0; k < 200; ++k) ts[k] = k / 199.0;
  std::shuffle(ts.begin(), ts.end(), std::mt19937_64(4));
  for (double t : ts) {
    ASSERT_EQ(insertPoint(tri, Vec2(t, t)).status, InsertStatus::Inserted);
    ASSERT_TRUE(validate(tri, delaunayCheck()).empty());
  }
  // A second line crossing the first.
  for (double t : ts) {
    const InsertResult r = insertPoint(tri, Vec2(t, 1 - t));
    ASSERT_TRUE(r.status == InsertStatus::Inserted || r.status == InsertStatus::Duplicate);
  }
  EXPECT_VALID(tri, delaunayCheck());
}

TEST(Triangulation2d, DuplicatesOutsideAndRefusals) {
  Triangulation2d tri(unitBox());
  const InsertResult first = insertPoint(tri, Vec2(0.3, 0.4));
  ASSERT_EQ(first.status, InsertStatus::Inserted);
  const std::uint64_t rev = tri.revision();
  const std::size_t nt = tri.numTriangles();
  const InsertResult dup = insertPoint(tri, Vec2(0.3, 0.4));
  EXPECT_EQ(dup.status, InsertStatus::Duplicate);
  EXPECT_EQ(dup.vertex, first.vertex);
  // A box corner is an existing vertex too.
  EXPECT_EQ(insertPoint(tri, tri.point(tri.corners()[3])).status, InsertStatus::Duplicate);
  EXPECT_EQ(insertPoint(tri, Vec2(10, 10)).status, InsertStatus::Outside);
  const InsertResult nan = insertPoint(tri, Vec2(std::nan(""), 0.5));
  EXPECT_EQ(nan.status, InsertStatus::Refused);
  EXPECT_EQ(nan.reason, RefuseReason::NotFinite);
  Mat2 singular;
  singular << 1, 2, 2, 4;
  const InsertResult bad = insertPoint(tri, Vec2(0.6, 0.6), singular);
  EXPECT_EQ(bad.status, InsertStatus::Refused);
  EXPECT_EQ(bad.reason, RefuseReason::BadTransform);
  // On the boundary of the box: the containing triangle cannot be star-shaped.
  const Vec2 onBoundary(0.5, tri.box().lo.y());
  const InsertResult edge = insertPoint(tri, onBoundary);
  EXPECT_EQ(edge.status, InsertStatus::Refused);
  EXPECT_EQ(edge.reason, RefuseReason::NotStarShaped);
  EXPECT_EQ(tri.revision(), rev);
  EXPECT_EQ(tri.numTriangles(), nt);
  EXPECT_VALID(tri, delaunayCheck());
}

TEST(Triangulation2d, PlanThenApplyAndStalePlan) {
  Triangulation2d tri(unitBox());
  const InsertPlan plan = planInsertion(tri, Vec2(0.5, 0.5));
  ASSERT_EQ(plan.status, InsertStatus::Inserted);
  EXPECT_VALID(tri, {});  // planning changes nothing (marks cleared)
  const InsertPlan stale = planInsertion(tri, Vec2(0.2, 0.7));
  ASSERT_EQ(applyInsertion(tri, plan).status, InsertStatus::Inserted);
  EXPECT_THROW(applyInsertion(tri, stale), MeshingError);
  EXPECT_VALID(tri, delaunayCheck());
}

TEST(Triangulation2d, ConstantAnisotropicMetric) {
  const Mat2 m = stretched(0.5, 0.01, 1.0);  // 100:1 stretch at 0.5 rad
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> pts(2000);
  for (Vec2& p : pts) p = Vec2(u(rng), u(rng));
  Triangulation2dOptions topt;
  topt.transform = m;  // initial diagonal Delaunay for M
  Triangulation2d tri(unitBox(), topt);
  EXPECT_VALID(tri, delaunayCheck(m));
  for (std::size_t k = 0; k < pts.size(); ++k) {
    ASSERT_EQ(insertPoint(tri, pts[k], m).status, InsertStatus::Inserted);
    if (k < 200) {
      ASSERT_TRUE(validate(tri, delaunayCheck(m)).empty()) << k;
    }
  }
  EXPECT_VALID(tri, delaunayCheck(m));
  // The metric-Delaunay triangulation is not the isotropic one.
  EXPECT_FALSE(validate(tri, delaunayCheck()).empty());
}

TEST(Triangulation2d, MetricTriangulationEqualsTriangulationOfTransformedPoints) {
  // A constant M: the in-circle tests see the same doubles M·x either way, so the
  // interior triangles coincide (the box differs; compare triangles among input points).
  const Mat2 m = stretched(-0.3, 0.05, 2.0);
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> pts(500), mpts(500);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    pts[k] = Vec2(u(rng), u(rng));
    mpts[k] = m * pts[k];
  }
  TriangulateOptions a, b;
  a.transform = m;
  a.spatialSort = b.spatialSort = false;
  const Triangulation2d ta = triangulatePoints(pts, a);
  const Triangulation2d tb = triangulatePoints(mpts, b);
  auto interior = [](const Triangulation2d& t) {
    std::set<std::array<std::uint32_t, 3>> s;
    for (const auto& tr : triangleSet(t))
      if (tr[0] >= 4) s.insert(tr);
    return s;
  };
  const auto sa = interior(ta), sb = interior(tb);
  std::size_t common = 0;
  for (const auto& t : sa) common += sb.count(t);
  // Triangles near the hull depend on the (different) box corners; the bulk must agree.
  EXPECT_GT(common, 0.8 * sa.size());
  EXPECT_VALID(ta, delaunayCheck(m));
}

TEST(Triangulation2d, VariableMetricStaysValid) {
  // A different strongly anisotropic M per point: no global Delaunay property, but the
  // star-shape pruning must keep every insertion valid.
  // First a mesh stretched along x, then points stretched along y and random directions.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0), ang(0.0, 3.14159);
  Triangulation2d tri(unitBox());
  for (int k = 0; k < 1000; ++k) insertPoint(tri, Vec2(u(rng), u(rng)), stretched(0.0, 1e-3, 1.0));
  ASSERT_TRUE(validate(tri).empty());
  std::size_t pruned = 0, inserted = 0;
  for (int k = 0; k < 3000; ++k) {
    const Mat2 m = stretched(k % 2 ? 1.5707963 : ang(rng), 1e-4 + 1e-3 * u(rng), 1.0);
    const InsertResult r = insertPoint(tri, Vec2(u(rng), u(rng)), m);
    ASSERT_NE(r.status, InsertStatus::Outside);
    inserted += r.status == InsertStatus::Inserted;
    pruned += r.pruned;
    if (k < 300) {
      ASSERT_TRUE(validate(tri).empty()) << k;
    }
  }
  EXPECT_VALID(tri, {});
  EXPECT_GT(inserted, 2900u);
  EXPECT_EQ(pruned, 0u);  // one M per insertion: star-shaped in exact arithmetic
}

namespace {

/// Per-triangle metric (thesis sec. 4.2.2, last paragraph): M at the triangle's centroid
/// from a field whose direction turns quickly.
class FieldConflict final : public ConflictTest {
 public:
  explicit FieldConflict(const Vec2& p) : p_(p) {}
  bool inConflict(const Triangulation2d& tri, TriId t) const override {
    const Vec2 a = tri.point(tri.vertex(t, 0)), b = tri.point(tri.vertex(t, 1)), c = tri.point(tri.vertex(t, 2));
    const Vec2 g = (a + b + c) / 3;
    const PlaneTransform m(stretched(20 * g.x() + 13 * g.y(), 1e-2, 1.0));
    return m.inCircle(a, b, c, m.apply(p_)) > 0;
  }

 private:
  Vec2 p_;
};

/// Not a circumcircle test at all: every triangle whose centroid lies in an L-shaped band
/// (one arm through p, the other turning away from it) — a cavity that is not star-shaped.
class LShapeConflict final : public ConflictTest {
 public:
  explicit LShapeConflict(const Vec2& p) : p_(p) {}
  bool inConflict(const Triangulation2d& tri, TriId t) const override {
    const Vec2 g = (tri.point(tri.vertex(t, 0)) + tri.point(tri.vertex(t, 1)) + tri.point(tri.vertex(t, 2))) / 3;
    const Vec2 d = g - p_;
    const bool arm1 = std::abs(d.y()) < 0.05 && d.x() > -0.1 && d.x() < 0.3;
    const bool arm2 = std::abs(d.x() - 0.3) < 0.05 && d.y() > -0.05 && d.y() < 0.3;
    return arm1 || arm2;
  }

 private:
  Vec2 p_;
};

}  // namespace

TEST(Triangulation2d, PerTriangleMetricConflictStaysValid) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Triangulation2d tri(unitBox());
  for (int k = 0; k < 3000; ++k) {
    const Vec2 p(u(rng), u(rng));
    const InsertResult r = applyInsertion(tri, planInsertion(tri, p, FieldConflict(p)));
    ASSERT_EQ(r.status, InsertStatus::Inserted);
    if (k < 200) {
      ASSERT_TRUE(validate(tri).empty()) << k;
    }
  }
  EXPECT_VALID(tri, {});
}

TEST(Triangulation2d, NonStarShapedConflictRegionIsPruned) {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Triangulation2d tri(unitBox());
  for (int k = 0; k < 2000; ++k) insertPoint(tri, Vec2(u(rng), u(rng)));
  std::size_t pruned = 0;
  for (int k = 0; k < 200; ++k) {
    const Vec2 p(0.1 + 0.5 * u(rng), 0.1 + 0.5 * u(rng));
    const InsertResult r = applyInsertion(tri, planInsertion(tri, p, LShapeConflict(p)));
    ASSERT_EQ(r.status, InsertStatus::Inserted);
    pruned += r.pruned;
    ASSERT_TRUE(validate(tri).empty()) << k;
  }
  EXPECT_GT(pruned, 0u);
}

TEST(Triangulation2d, CavityNeverCrossesConstrainedEdges) {
  // A square contour of 4×10 collinear points: all contour segments are Delaunay edges.
  Triangulation2d tri(unitBox());
  std::vector<VertexId> contour;
  const int n = 10;
  auto corner = [](int side, int k, int n) {
    const double t = static_cast<double>(k) / n;
    switch (side) {
      case 0: return Vec2(0.2 + 0.6 * t, 0.2);
      case 1: return Vec2(0.8, 0.2 + 0.6 * t);
      case 2: return Vec2(0.8 - 0.6 * t, 0.8);
      default: return Vec2(0.2, 0.8 - 0.6 * t);
    }
  };
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < n; ++k) {
      const InsertResult r = insertPoint(tri, corner(side, k, n));
      ASSERT_EQ(r.status, InsertStatus::Inserted);
      contour.push_back(r.vertex);
    }
  for (std::size_t k = 0; k < contour.size(); ++k)
    ASSERT_TRUE(tri.setConstrainedEdge(contour[k], contour[(k + 1) % contour.size()]));
  EXPECT_VALID(tri, delaunayCheck());
  // Many points on both sides, some very close to the contour.
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0), eps(-1e-3, 1e-3);
  for (int k = 0; k < 2000; ++k) {
    Vec2 p(u(rng), u(rng));
    if (k % 3 == 0) p = corner(k % 4, 0, n) + (corner(k % 4, 1, n) - corner(k % 4, 0, n)) * u(rng) + Vec2(eps(rng), eps(rng));
    const InsertResult r = insertPoint(tri, p);
    ASSERT_NE(r.status, InsertStatus::Outside);
    if (k < 200) {
      ASSERT_TRUE(validate(tri, delaunayCheck()).empty()) << k;
    }
  }
  for (std::size_t k = 0; k < contour.size(); ++k) {
    TriId t;
    int i = 0;
    ASSERT_TRUE(tri.findEdge(contour[k], contour[(k + 1) % contour.size()], t, i)) << k;
    EXPECT_TRUE(tri.isConstrained(t, i));
  }
  // Constrained Delaunay: every unconstrained edge is locally Delaunay.
  EXPECT_VALID(tri, delaunayCheck());
  // A point exactly on a constrained edge is refused, nothing changes.
  const std::uint64_t rev = tri.revision();
  const Vec2 mid = 0.5 * (tri.point(contour[0]) + tri.point(contour[1]));
  const InsertResult r = insertPoint(tri, mid);
  EXPECT_EQ(r.status, InsertStatus::Refused);
  EXPECT_EQ(r.reason, RefuseReason::NotStarShaped);
  EXPECT_EQ(tri.revision(), rev);
}

TEST(Triangulation2d, ExtremeCoordinates) {
  for (double scale : {1e-100, 1e100}) {
    for (double offset : {0.0, 1e6}) {
      std::mt19937_64 rng(9);
      std::uniform_real_distribution<double> u(0.0, 1.0);
      std::vector<Vec2> pts(300);
      for (Vec2& p : pts) p = Vec2(offset + u(rng), offset + u(rng)) * scale;
      for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) pts.push_back(Vec2(offset + 0.1 * i, offset + 0.1 * j) * scale);
      TriangulateResult res;
      const Triangulation2d tri = triangulatePoints(pts, {}, &res);
      EXPECT_EQ(res.refused, 0u);
      EXPECT_EQ(res.inserted + res.duplicates, pts.size());
      EXPECT_VALID(tri, delaunayCheck());
    }
  }
}

TEST(Triangulation2d, LocateClassifiesExactly) {
  Triangulation2d tri(unitBox());
  const VertexId a = insertPoint(tri, Vec2(0.25, 0.25)).vertex;
  const VertexId b = insertPoint(tri, Vec2(0.75, 0.25)).vertex;
  insertPoint(tri, Vec2(0.5, 0.75));
  const LocateResult onV = locate(tri, Vec2(0.75, 0.25));
  ASSERT_EQ(onV.where, Location::OnVertex);
  EXPECT_EQ(tri.vertex(onV.tri, onV.index), b);
  TriId t;
  int i = 0;
  ASSERT_TRUE(tri.findEdge(a, b, t, i) || tri.findEdge(b, a, t, i));
  const LocateResult onE = locate(tri, Vec2(0.5, 0.25));
  ASSERT_EQ(onE.where, Location::OnEdge);
  const VertexId e0 = tri.vertex(onE.tri, kNext[onE.index]), e1 = tri.vertex(onE.tri, kPrev[onE.index]);
  EXPECT_TRUE((e0 == a && e1 == b) || (e0 == b && e1 == a));
  EXPECT_EQ(locate(tri, Vec2(0.5, 0.4)).where, Location::Inside);
  EXPECT_EQ(locate(tri, Vec2(-5, 0.4)).where, Location::Outside);
  // From every start triangle the walk finds the same answer.
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    if (!tri.isAlive(TriId(k))) continue;
    const LocateResult r = locate(tri, Vec2(0.5, 0.4), TriId(k));
    EXPECT_EQ(r.where, Location::Inside);
    EXPECT_EQ(r.tri, locate(tri, Vec2(0.5, 0.4)).tri);
  }
}
