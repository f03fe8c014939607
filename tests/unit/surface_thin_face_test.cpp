// Boundary sizing at thin faces and tiny CAD edges (mesher/sizing/BoundaryGaps.h,
// BoundaryUpdate.h): gaps of a strip, the face's width, its own h_min, and whole models
// meshed through meshSurfaces (a strip narrower than h_min; a tiny edge next to long ones).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include <Eigen/Geometry>

#include "mesher/control/CSAnalytic2d.h"
#include "mesher/control/CSQuadtree2d.h"
#include "mesher/sizing/BoundaryGaps.h"
#include "mesher/sizing/BoundaryUpdate.h"
#include "tests/unit/contour_test_models.h"
#include "tests/unit/mesh_model_fixture.h"

namespace aniso::test {
namespace {

/// A rectangle [0, length] × [0, width] as one loop, n nodes per long side, 1 segment per end.
FaceBoundary strip(double length, double width, int n) {
  FaceBoundary b;
  b.face = 0;
  b.loops.emplace_back();
  for (int i = 0; i <= n; ++i) b.loops[0].push_back({Vec2(length * i / n, 0), i});                  // bottom
  for (int i = n; i >= 0; --i) b.loops[0].push_back({Vec2(length * i / n, width), 2 * n + 1 - i});  // top
  return b;
}

CSAnalytic2d uniform(double h) {
  return CSAnalytic2d(box(-1, -1, 20, 20), [h](const Vec2&) { return Metric2d::isotropic(h); });
}

/// Referee mean ratio of a 3D triangle (4√3 A / Σ l²).
double meanRatio(const SurfaceMesh& m, const std::array<int, 3>& t) {
  const Vec3 &a = m.nodes[t[0]], &b = m.nodes[t[1]], &c = m.nodes[t[2]];
  const double area = 0.5 * (b - a).cross(c - a).norm();
  const double l2 = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return 4 * std::sqrt(3.0) * area / l2;
}

/// A planar face: the polygon `pts` (counter-clockwise, z = 0), one straight edge per side.
Model polygonFace(const std::vector<Vec2>& pts) {
  ModelBuilder b;
  Box2 bb;
  for (const Vec2& p : pts) bb.add(p);
  const int f = b.face(xyPlane(bb.lo.x() - 1, bb.hi.x() + 1, bb.lo.y() - 1, bb.hi.y() + 1), bb);
  std::vector<int> vs;
  for (const Vec2& p : pts) vs.push_back(b.vertex({p.x(), p.y(), 0}));
  polygonLoop(b, f, vs, true);
  return b.m;
}

/// The model meshed with the acceptance options (--hmax-rel 0.02 --anisotropy 1), checked
/// to be made and valid; its triangles' mean ratio: mean, worst, and the total area.
struct Meshed {
  SurfaceMeshResult r;
  double mean = 0, worst = 1, area = 0;
};

Meshed meshIsotropic(const Model& m) {
  SurfaceMesherInput in;
  in.model = &m;
  in.options.sizing.hmaxRel = 0.02;
  in.options.sizing.anisotropy = 1;
  in.options.threads = 1;
  Meshed out{meshSurfaces(in)};
  EXPECT_TRUE(out.r.ok());
  EXPECT_TRUE(out.r.mesh.validate().empty());
  const SurfaceMesh& mesh = out.r.mesh;
  for (const auto& t : mesh.triangles) {
    const double q = meanRatio(mesh, t);
    out.mean += q / static_cast<double>(mesh.triangles.size());
    out.worst = std::min(out.worst, q);
    out.area += 0.5 * (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]).norm();
  }
  return out;
}

}  // namespace

TEST(SurfaceThinFace, GapsOfAStripAndItsWidth) {
  const FaceBoundary b = strip(10, 0.01, 10);  // segments of length 1 across a gap of 0.01
  const CSAnalytic2d cs = uniform(1.0);
  const BoundarySegments segs = boundarySegments(cs, b);
  ASSERT_EQ(segs.segments.size(), 22u);
  EXPECT_NEAR(segs.loopLength[0], 20.02, 1e-9);
  const std::vector<BoundaryGap> gaps = findBoundaryGaps(cs, segs, 0.5, 0.0);
  // Every long segment sees the other side 0.01 away; the two ends only see their
  // neighbours around a corner (the same side), so they have no gap.
  ASSERT_EQ(gaps.size(), 20u);
  for (const BoundaryGap& g : gaps) {
    EXPECT_NEAR(g.width(), 0.01, 1e-12);
    EXPECT_NEAR(g.metricWidth, 0.01, 1e-12);
    EXPECT_NE(segs.segments[g.segment].a.y(), segs.segments[g.other].a.y());  // the other side
  }
  // Width: 20 segments of length 1 at 0.01, two ends of 0.01 at the cap.
  EXPECT_NEAR(thinFaceWidth(segs, gaps, 0.1), (20 * 0.01 + 2 * 0.01 * 0.1) / 20.02, 1e-12);
  // A coarse search (metric width 0.01 < lMin needed) finds nothing on a fine metric...
  const CSAnalytic2d fine = uniform(0.005);
  EXPECT_TRUE(findBoundaryGaps(fine, boundarySegments(fine, b), 0.5, 0.0).empty());
  // ... unless the real width is below minWidth: the thin face is seen in every round.
  EXPECT_EQ(findBoundaryGaps(fine, boundarySegments(fine, b), 0.5, 0.02).size(), 20u);
}

TEST(SurfaceThinFace, FaceMinSizePolicy) {
  BoundaryUpdateOptions o;
  o.hMin = 1e-3;
  EXPECT_EQ(faceMinSize(2e-3, o), 1e-3);     // wide face: h_min
  EXPECT_EQ(faceMinSize(0.9e-3, o), 1e-3);   // only locally thin: h_min
  EXPECT_EQ(faceMinSize(3.8e-4, o), 3.8e-4); // thin: its width
  EXPECT_EQ(faceMinSize(1e-6, o), 1e-4);     // bounded by thinFaceRatio · h_min
  o.cadTolerance = 5e-5;
  EXPECT_EQ(faceMinSize(1e-6, o), 5e-4);     // and by 10 × the CAD tolerance
  o.cadTolerance = 1;
  EXPECT_EQ(faceMinSize(1e-6, o), 1e-3);     // never above h_min
  o.cadTolerance = 0;
  o.thinFaces = false;                        // a volume mesh: h_min for every face
  EXPECT_EQ(faceMinSize(3.8e-4, o), 1e-3);
  EXPECT_EQ(faceMinSize(1e-6, o), 1e-3);
}

TEST(SurfaceThinFace, UpdateRefinesAThinStripToItsWidth) {
  // A strip 0.004 wide, h_min 0.01: the face's own h_min is its width, and the sources
  // ask for elements of that size on both sides.
  const FaceBoundary b = strip(10, 0.004, 10);
  SizingParameters params;
  params.anisotropy = 1;
  CSQuadtree2d cs(box(-0.1, -0.1, 10.1, 10.1), params);
  cs.setContinuousSource(CSAnalytic2d(box(-0.1, -0.1, 10.1, 10.1), [](const Vec2&) { return Metric2d::isotropic(1); }));
  BoundaryUpdateOptions o;
  o.hMin = 0.01;
  const BoundaryUpdateStats s = updateFromBoundary(cs, b, params, o);
  EXPECT_NEAR(s.faceMinSize, 0.004, 2e-4);
  EXPECT_GT(s.gaps, 0);
  const double h = cs.getMetric(Vec2(5.5, 0)).sizing.angleLengths().h2;
  EXPECT_LT(h, 0.006);
  EXPECT_GT(h, 0.003);
  // The segments are 1 long (a first discretization at h_max): between the sources at their
  // ends and midpoints the size stays near the width too, in one update.
  for (const double x : {2.2, 5.3, 5.77, 8.61})
    EXPECT_LT(cs.getMetric(Vec2(x, 0.002)).sizing.angleLengths().h2, 0.01) << "at x = " << x;
  // The same strip 0.004 wide with h_min 0.0015 is not thin (width > h_min / 2) but a strip
  // (its whole length faces the other side) wider than 2 h_min: sources of the gap's size,
  // h_min kept. With the strip rule off (stripFraction 1) its gaps get no sources unless
  // the vicinity rule is on for every face; with h_min 0.0025 the gap is narrower than
  // 2 h_min and left.
  const auto fresh = [&params] {
    auto c = std::make_unique<CSQuadtree2d>(box(-0.1, -0.1, 10.1, 10.1), params);
    c->setContinuousSource(CSAnalytic2d(box(-0.1, -0.1, 10.1, 10.1), [](const Vec2&) { return Metric2d::isotropic(1); }));
    return c;
  };
  o.hMin = 0.0015;
  const BoundaryUpdateStats st = updateFromBoundary(*fresh(), b, params, o);
  EXPECT_EQ(st.faceMinSize, 0.0015);
  EXPECT_GT(st.gaps, 0);
  o.hMin = 0.0025;
  const BoundaryUpdateStats narrow = updateFromBoundary(*fresh(), b, params, o);
  EXPECT_EQ(narrow.gaps, 0);
  EXPECT_GT(narrow.unresolvedGaps, 0);
  o.hMin = 0.0015;
  o.stripFraction = 1;
  EXPECT_EQ(updateFromBoundary(*fresh(), b, params, o).gaps, 0);
  o.vicinity = true;
  EXPECT_GT(updateFromBoundary(*fresh(), b, params, o).gaps, 0);
}

TEST(SurfaceThinFace, StripNarrowerThanHminMeshesWellShaped) {
  // 10 × 4e-4 (h_min = 1e-4 · diagonal = 1e-3): one element across, each about as long as
  // the strip is wide, instead of needles h_min long.
  const Meshed m = meshIsotropic(polygonFace({{0, 0}, {10, 0}, {10, 4e-4}, {0, 4e-4}}));
  EXPECT_NEAR(m.area, 4e-3, 1e-9);
  EXPECT_GT(m.mean, 0.85);  // 0.05 with h_min as the floor
  EXPECT_GT(m.worst, 0.2);
  EXPECT_GT(m.r.mesh.triangles.size(), 20000u);
  EXPECT_LT(m.r.mesh.triangles.size(), 100000u);  // bounded by the width, not by 0.1 h_min
}

TEST(SurfaceThinFace, TinyEdgeNextToLongOnesGradesAway) {
  // A 10 × 5 rectangle with one corner cut by an edge 0.01 long (20 h_min, 1/25 of h_max):
  // the short-segment rule grades the size away from it, so the triangles at the tiny edge
  // are well shaped and no needle is left anywhere.
  const double c = 0.01 / std::sqrt(2.0);
  const Meshed m = meshIsotropic(polygonFace({{0, 0}, {10 - c, 0}, {10, c}, {10, 5}, {0, 5}}));
  EXPECT_NEAR(m.area, 50 - c * c / 2, 1e-9);
  EXPECT_GT(m.worst, 0.3);
  EXPECT_GT(m.mean, 0.9);
}

}  // namespace aniso::test

namespace aniso::test {

TEST(SurfaceThinFace, StepFaceEndsGetNoSourceInAVolumeMesh) {
  // A strip 0.004 wide, h_min 0.01, in a volume mesh: a step of the CAD. Its ends (segments
  // 0.004 long) ask for nothing; the same short segment on a wide face (a cut corner) does.
  SizingParameters params;
  params.anisotropy = 1;
  const auto fresh = [&params] {
    auto c = std::make_unique<CSQuadtree2d>(box(-0.1, -0.1, 10.1, 10.1), params);
    c->setContinuousSource(CSAnalytic2d(box(-0.1, -0.1, 10.1, 10.1), [](const Vec2&) { return Metric2d::isotropic(1); }));
    return c;
  };
  BoundaryUpdateOptions o;
  o.hMin = 0.01;
  o.thinFaces = false;
  auto cs = fresh();
  const BoundaryUpdateStats s = updateFromBoundary(*cs, strip(10, 0.004, 10), params, o);
  EXPECT_EQ(s.stepEnds, 2);
  EXPECT_EQ(s.shortSegments, 0);
  EXPECT_GT(cs->getMetric(Vec2(0, 0.002)).sizing.angleLengths().h2, 0.5);
  // for a surface mesh the strip is a thin face: its ends keep their sources
  o.thinFaces = true;
  EXPECT_EQ(updateFromBoundary(*fresh(), strip(10, 0.004, 10), params, o).stepEnds, 0);
  // a wide face with a short segment (a corner cut 0.004 long): its source stays
  o.thinFaces = false;
  FaceBoundary cut;
  cut.face = 0;
  cut.loops.emplace_back();
  const double c = 0.004 / std::sqrt(2.0);
  int id = 0;
  for (const Vec2& p : {Vec2(0, 0), Vec2(5, 0), Vec2(10 - c, 0), Vec2(10, c), Vec2(10, 5), Vec2(5, 5), Vec2(0, 5)})
    cut.loops[0].push_back({p, id++});
  auto cs2 = fresh();
  const BoundaryUpdateStats w = updateFromBoundary(*cs2, cut, params, o);
  EXPECT_EQ(w.stepEnds, 0);
  EXPECT_GE(w.shortSegments, 1);
  EXPECT_LT(cs2->getMetric(Vec2(10 - c / 2, c / 2)).sizing.angleLengths().h2, 0.1);
}


TEST(SurfaceThinFace, AStepWhoseSidesNodesDoNotFaceEachOtherGetsNoGapSource) {
  // A strip 0.004 wide, h_min 0.01, in a volume mesh (KiCad's pin sockets: 1 um steps round
  // the pin holes), its top nodes 0.03 short of the bottom ones. A top node lies beyond the
  // end of the bottom segment its segment faces: measured to that segment alone, the width
  // there was 0.03, above the narrowest resolved gap (0.02), and a source of 0.03 went in.
  // Measured to the other side (that segment and the ones next to it), it is 0.004: none.
  SizingParameters params;
  params.anisotropy = 1;
  const Box2 area = box(-0.1, -0.1, 10.1, 10.1);
  CSQuadtree2d cs(area, params);
  cs.setContinuousSource(CSAnalytic2d(area, [](const Vec2&) { return Metric2d::isotropic(1); }));
  FaceBoundary b;
  b.face = 0;
  b.loops.emplace_back();
  int id = 0;
  for (int i = 0; i <= 10; ++i) b.loops[0].push_back({Vec2(i, 0), id++});
  for (int i = 10; i >= 0; --i) b.loops[0].push_back({Vec2(i == 0 || i == 10 ? i : i - 0.03, 0.004), id++});
  BoundaryUpdateOptions o;
  o.hMin = 0.01;
  o.thinFaces = false;
  const BoundaryUpdateStats s = updateFromBoundary(cs, b, params, o);
  EXPECT_EQ(s.gaps, 0);
  EXPECT_GT(s.unresolvedGaps, 0);
  for (const double x : {0.97, 3.0, 5.5, 9.97}) EXPECT_GT(cs.getMetric(Vec2(x, 0.002)).sizing.angleLengths().h1, 0.5) << x;
}

}  // namespace aniso::test
