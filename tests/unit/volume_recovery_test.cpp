// Unit tests of the boundary-recovery operators on hand-made configurations: the exact
// crossing tests, the pipe, pipe reduction by each kind of flip (T23, T32 as a 3-ring
// edge removal, T44 as a 4-ring edge removal), the region replacement's check.
#include <gtest/gtest.h>

#include <string>

#include "mesher/delaunay3d/Delaunay3d.h"
#include "mesher/delaunay3d/Validate.h"
#include "mesher/volume/BoundaryCrossing.h"
#include "mesher/volume/MeshQueries.h"
#include "mesher/volume/Pipe.h"
#include "mesher/volume/PipeReduction.h"
#include "mesher/volume/RegionReplace.h"
#include "mesher/volume/SegmentCrossing.h"

using namespace aniso;
using namespace aniso::volume;
using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

namespace {

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += x + "\n";
  return s;
}

struct Built {
  TetMesh mesh;
  std::vector<VertexId> v;  ///< vertex of each input point
};

Built delaunay(const std::vector<Vec3>& pts) {
  Built b;
  del3d::DelaunayOptions o;
  o.boxMargin = 10;  // box corners far away: the hull of the points is as without them
  const del3d::DelaunayResult r = del3d::buildDelaunay(b.mesh, pts, o);
  b.v = r.vertexOf;
  return b;
}

bool hasEdge(const TetMesh& m, VertexId a, VertexId b) {
  std::vector<TetId> star;
  return findEdge(m, a, b, star).valid();
}

const EdgeGuard kNoGuard = [](VertexId, VertexId) { return false; };

}  // namespace

TEST(VolumeSegmentCrossing, TransversalCoplanarSharedAndDegenerate) {
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
  const double up[3] = {0.2, 0.2, 1}, down[3] = {0.2, 0.2, -1}, away[3] = {2, 2, -1};
  EXPECT_EQ(segmentCrossesTriangle(up, down, a, b, c), Cross::Interior);
  EXPECT_EQ(segmentCrossesTriangle(up, away, a, b, c), Cross::None);
  // Coplanar: from vertex a into the angle at a, and across an edge.
  const double far[3] = {1, 1, 0}, left[3] = {-1, 0.3, 0}, right[3] = {1, 0.3, 0};
  EXPECT_EQ(segmentCrossesTriangle(a, far, a, b, c), Cross::Interior);
  EXPECT_EQ(segmentCrossesTriangle(left, right, a, b, c), Cross::Interior);
  EXPECT_EQ(segmentCrossesTriangle(a, b, a, b, c), Cross::None);  // an edge of it
  // An endpoint strictly inside: degenerate.
  const double inside[3] = {0.2, 0.2, 0};
  EXPECT_EQ(segmentCrossesTriangle(inside, up, a, b, c), Cross::Degenerate);
  // Segments: crossing in a plane, skew, touching at an endpoint, collinear overlap.
  const double p[3] = {0.5, -1, 0}, q[3] = {0.5, 1, 0}, r[3] = {0.5, -1, 1};
  EXPECT_EQ(segmentsCross(a, b, p, q), Cross::Interior);
  EXPECT_EQ(segmentsCross(a, b, r, q), Cross::None);
  EXPECT_EQ(segmentsCross(a, b, b, q), Cross::None);
  const double m1[3] = {0.5, 0, 0}, m2[3] = {2, 0, 0};
  EXPECT_EQ(segmentsCross(a, b, m1, m2), Cross::Degenerate);
}

TEST(VolumeRecovery, MissingEdgeThroughAFaceNeedsT23) {
  // A tall bipyramid: Delaunay keeps the two tets on triangle abc, edge de is missing.
  const Built b0 = delaunay({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3, 0.9, 0), Vec3(0.4, 0.3, 3), Vec3(0.45, 0.3, -3)});
  Built b = b0;
  const VertexId d = b.v[3], e = b.v[4];
  ASSERT_FALSE(hasEdge(b.mesh, d, e));
  Pipe pipe;
  segmentPipe(b.mesh, d, e, pipe);
  EXPECT_FALSE(pipe.degenerate);
  EXPECT_GE(pipe.faces.size(), 1u);
  FlipCounters fc;
  EXPECT_TRUE(reduceEdgePipe(b.mesh, d, e, kNoGuard, 32, fc));
  EXPECT_TRUE(hasEdge(b.mesh, d, e));
  EXPECT_GE(fc.flips23, 1u);
  EXPECT_EQ(joined(del3d::validate(b.mesh)), "");
}

TEST(VolumeRecovery, MissingFaceAroundAnEdgeNeedsT32) {
  // A flat bipyramid: Delaunay puts three tets around de, face abc is missing.
  Built b = delaunay({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0.9, 0), Vec3(0.5, 0.3, 0.1), Vec3(0.5, 0.3, -0.1)});
  const VertexId a = b.v[0], c1 = b.v[1], c2 = b.v[2];
  std::vector<TetId> star;
  ASSERT_FALSE(findFace(b.mesh, a, c1, c2, star).valid());
  ASSERT_TRUE(hasEdge(b.mesh, a, c1) && hasEdge(b.mesh, c1, c2) && hasEdge(b.mesh, c2, a));
  Pipe pipe;
  trianglePipe(b.mesh, a, c1, c2, pipe);
  EXPECT_EQ(pipe.edges.size(), 1u);
  FlipCounters fc;
  EXPECT_TRUE(reduceFacePipe(b.mesh, a, c1, c2, kNoGuard, 32, fc));
  EXPECT_TRUE(findFace(b.mesh, a, c1, c2, star).valid());
  EXPECT_GE(fc.removals, 1u);
  EXPECT_EQ(joined(del3d::validate(b.mesh)), "");
}

TEST(VolumeRecovery, MissingDiagonalOfACoplanarSquareNeedsT44) {
  // A flattened octahedron: Delaunay joins the apexes; a diagonal of the square is missing
  // and crosses the axis, which has four tets around it (coplanar ring).
  Built b = delaunay({Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(-2, 0, 0), Vec3(0, -2, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)});
  const VertexId s0 = b.v[0], s2 = b.v[2];
  ASSERT_TRUE(hasEdge(b.mesh, b.v[4], b.v[5]));
  ASSERT_FALSE(hasEdge(b.mesh, s0, s2));
  FlipCounters fc;
  EXPECT_TRUE(reduceEdgePipe(b.mesh, s0, s2, kNoGuard, 32, fc));
  EXPECT_TRUE(hasEdge(b.mesh, s0, s2));
  EXPECT_FALSE(hasEdge(b.mesh, b.v[4], b.v[5]));
  EXPECT_GE(fc.removals, 1u);
  EXPECT_EQ(joined(del3d::validate(b.mesh)), "");
}

TEST(VolumeRecovery, ProtectedEdgeIsNotFlippedAway) {
  Built b = delaunay({Vec3(2, 0, 0), Vec3(0, 2, 0), Vec3(-2, 0, 0), Vec3(0, -2, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)});
  const VertexId e = b.v[4], f = b.v[5];
  const EdgeGuard guard = [&](VertexId x, VertexId y) { return (x == e && y == f) || (x == f && y == e); };
  FlipCounters fc;
  EXPECT_FALSE(reduceEdgePipe(b.mesh, b.v[0], b.v[2], guard, 32, fc));
  EXPECT_TRUE(hasEdge(b.mesh, e, f));
  EXPECT_EQ(joined(del3d::validate(b.mesh)), "");
}

TEST(VolumeRecovery, RegionReplaceRefusesAnotherBoundary) {
  Built b = delaunay({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0.3, 0.3, 0.3)});
  std::vector<TetId> star;
  vertexStar(b.mesh, b.v[4], star);
  ASSERT_GE(star.size(), 4u);
  const std::size_t before = b.mesh.numTets();
  // One tet over the first face only: does not close the star's boundary.
  const std::array<VertexId, 4> q = {b.mesh.vertex(star[0], 0), b.mesh.vertex(star[0], 1), b.mesh.vertex(star[0], 2),
                                     b.mesh.vertex(star[0], 3)};
  const std::vector<std::array<VertexId, 4>> quads{q};
  EXPECT_FALSE(replaceRegion(b.mesh, star, quads));
  EXPECT_EQ(b.mesh.numTets(), before);
  EXPECT_EQ(joined(del3d::validate(b.mesh)), "");
}

TEST(VolumeRecovery, BoundaryCrossingNamesThePresentBoundaryEntityCrossed) {
  // The square's two diagonals: Delaunay keeps one (a flat square with apexes above and
  // below has s1-s3 or s0-s2); as boundary edges both, the missing one crosses the other.
  Built b = delaunay({Vec3(2, 0, 0), Vec3(0, 2.1, 0), Vec3(-2, 0, 0), Vec3(0, -2.1, 0), Vec3(0.1, 0, 3), Vec3(0, 0.1, -3)});
  const VertexId s0 = b.v[0], s1 = b.v[1], s2 = b.v[2], s3 = b.v[3];
  const bool first = hasEdge(b.mesh, s0, s2);
  ASSERT_NE(first, hasEdge(b.mesh, s1, s3));
  const VertexId ma = first ? s1 : s0, mb = first ? s3 : s2;    // missing
  const VertexId pa = first ? s0 : s1, pb = first ? s2 : s3;    // present
  const EdgeGuard both = [&](VertexId x, VertexId y) {
    const auto is = [&](VertexId u, VertexId v) { return (x == u && y == v) || (x == v && y == u); };
    return is(pa, pb) || is(ma, mb);
  };
  Pipe pipe;
  const std::vector<VertexId> x = boundaryCrossing(b.mesh, ma, mb, both, pipe);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_TRUE((x[0] == pa && x[1] == pb) || (x[0] == pb && x[1] == pa));
  // Not a boundary edge: no evidence.
  EXPECT_TRUE(boundaryCrossing(b.mesh, ma, mb, kNoGuard, pipe).empty());
}
