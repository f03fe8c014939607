// unfoldSurface (mesher/volume/UnfoldSurface.h): folds of the surface mesh mended before
// the volume is meshed, on hand-made planar faces (z = 0, normal +z).
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "mesher/volume/FoldRegion.h"
#include "mesher/volume/UnfoldSurface.h"

using namespace aniso;

namespace {

NodeOn onFace() { return NodeOn{NodeOn::Kind::Face, 0, 0, Vec2(0, 0)}; }
NodeOn onEdge() { return NodeOn{NodeOn::Kind::Edge, 0, 0, Vec2(0, 0)}; }

/// Directed edges used once: the rim of the mesh (each face here is one disc).
std::set<std::pair<int, int>> rim(const SurfaceMesh& m) {
  std::map<std::pair<int, int>, int> net;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a < b) ++net[{a, b}];
      else --net[{b, a}];
    }
  std::set<std::pair<int, int>> out;
  for (const auto& [e, n] : net)
    if (n == 1) out.insert(e);
    else if (n == -1) out.insert({e.second, e.first});
  return out;
}

double signedArea(const SurfaceMesh& m) {
  double a = 0;
  for (const auto& t : m.triangles) a += 0.5 * (m.nodes[t[1]] - m.nodes[t[0]]).cross(m.nodes[t[2]] - m.nodes[t[0]]).z();
  return a;
}

void expectUpward(const SurfaceMesh& m) {
  for (const auto& t : m.triangles)
    EXPECT_GT((m.nodes[t[1]] - m.nodes[t[0]]).cross(m.nodes[t[2]] - m.nodes[t[0]]).z(), 0)
        << t[0] << " " << t[1] << " " << t[2];
}

/// A unit square of rim nodes with one face node in the middle whose star is a fan;
/// `folded` adds a cap: the fan's node pushed over the rim of one side, so one of its
/// triangles turns over.
SurfaceMesh fan(bool folded) {
  SurfaceMesh m;
  m.addNode(Vec3(0, 0, 0), onEdge());
  m.addNode(Vec3(1, 0, 0), onEdge());
  m.addNode(Vec3(1, 1, 0), onEdge());
  m.addNode(Vec3(0, 1, 0), onEdge());
  m.addNode(folded ? Vec3(0.5, -0.05, 0) : Vec3(0.5, 0.5, 0), onFace());
  m.addNode(Vec3(0.5, 0, 0), onEdge());  // a rim node on the bottom side
  for (const auto& t : std::vector<std::array<int, 3>>{{0, 5, 4}, {5, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}) {
    m.triangles.push_back(t);
    m.triangleFace.push_back(0);
  }
  return m;
}

}  // namespace

TEST(UnfoldSurface, LeavesAnUnfoldedMeshAsItIs) {
  SurfaceMesh m = fan(false);
  const auto before = m.triangles;
  EXPECT_EQ(countFoldedEdges(m), 0);
  const UnfoldStats s = unfoldSurface(m);
  EXPECT_EQ(s.foldedBefore, 0);
  EXPECT_EQ(s.flips, 0);
  EXPECT_EQ(m.triangles, before);
}

TEST(UnfoldSurface, NodePushedOverTheRimIsMendedKeepingTheRim) {
  SurfaceMesh m = fan(true);
  ASSERT_GT(countFoldedEdges(m), 0);
  const auto rimBefore = rim(m);
  const UnfoldStats s = unfoldSurface(m);
  EXPECT_GT(s.foldedBefore, 0);
  EXPECT_EQ(s.foldedAfter, 0);
  EXPECT_EQ(countFoldedEdges(m), 0);
  EXPECT_EQ(rim(m), rimBefore);
  EXPECT_NEAR(signedArea(m), 1.0, 1e-12);
  expectUpward(m);
  EXPECT_TRUE(m.validate().empty());
}

TEST(UnfoldSurface, PocketOfRimSliversBecomesAFanFromTheApex) {
  // Rim nodes 0..4 along y = 0 bulging by 1e-4 out of the plane (three nearly collinear
  // rim nodes make slivers standing across the face), apex 5 above; the face's mesh has
  // the chord (0, 4) with slivers between it and the rim.
  SurfaceMesh m;
  for (int k = 0; k <= 4; ++k) m.addNode(Vec3(0.25 * k, 0, (k % 2 ? 1e-4 : -1e-4)), onEdge());
  m.addNode(Vec3(0.5, 0.6, 0), onFace());
  for (const auto& t : std::vector<std::array<int, 3>>{{0, 4, 5}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}}) {
    m.triangles.push_back(t);
    m.triangleFace.push_back(0);
  }
  ASSERT_GT(countFoldedEdges(m), 0);
  const auto rimBefore = rim(m);
  const UnfoldStats s = unfoldSurface(m);
  EXPECT_EQ(s.foldedAfter, 0);
  EXPECT_EQ(countFoldedEdges(m), 0);
  EXPECT_EQ(rim(m), rimBefore);
  EXPECT_EQ(m.triangles.size(), 4u);
  for (const auto& t : m.triangles) EXPECT_TRUE(t[0] == 5 || t[1] == 5 || t[2] == 5);
  EXPECT_TRUE(m.validate().empty());
}

TEST(UnfoldSurface, OtherFacesKeepTheirTriangles) {
  SurfaceMesh m = fan(true);
  // A second face sharing the bottom rim (a wall below it), untouched by the mending.
  const int low = m.addNode(Vec3(0.5, 0, -1), NodeOn{NodeOn::Kind::Face, 1, 0, Vec2(0, 0)});
  m.triangles.push_back({5, 0, low});
  m.triangleFace.push_back(1);
  m.triangles.push_back({1, 5, low});
  m.triangleFace.push_back(1);
  unfoldSurface(m);
  EXPECT_EQ(countFoldedEdges(m), 0);
  int second = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (m.triangleFace[t] == 1) ++second;
  EXPECT_EQ(second, 2);
}

// A CAD vertex inside a face (a pole) whose star has one triangle turned over — the vertex
// lies beyond the edge of its star's inner triangle — cannot be dropped: the region is
// re-triangulated as the fan from it (FoldRegion.h step 4), the face nodes inside dropped.
TEST(FoldRegion, AVertexInsideTheFoldIsKeptAsTheHubOfAFan) {
  SurfaceMesh m;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}) m.addNode(p, onEdge());
  const int f1 = m.addNode(Vec3(0.6, 0.3, 0), onFace()), f2 = m.addNode(Vec3(0.6, 0.7, 0), onFace()),
            f3 = m.addNode(Vec3(0.9, 0.5, 0), onFace());
  // the hub belongs inside (f1, f3, f2), at (0.75, 0.5); at (0.5, 0.5) (f2, f1, hub) turns over
  const int hub = m.addNode(Vec3(0.5, 0.5, 0), NodeOn{NodeOn::Kind::Vertex, 0, 0, Vec2(0, 0)});
  const std::vector<std::array<int, 3>> tris = {{0, 1, f1},  {1, f3, f1},  {1, 2, f3},    {2, f2, f3},
                                                {2, 3, f2},  {3, 0, f2},   {0, f1, f2},   {f1, f3, hub},
                                                {f3, f2, hub}, {f2, f1, hub}};
  for (const auto& t : tris) {
    m.triangles.push_back(t);
    m.triangleFace.push_back(0);
  }
  ASSERT_GT(countFoldedEdges(m), 0);
  std::vector<int> useCount(m.nodes.size(), 0);
  std::set<std::array<int, 3>> existing;
  for (const auto& t : tris) {
    for (const int v : t) ++useCount[v];
    std::array<int, 3> s = t;
    std::sort(s.begin(), s.end());
    existing.insert(s);
  }
  FoldRepair fix;
  ASSERT_TRUE(retriangulateFold(m, tris, {7, 8, 9}, useCount, existing, fix));
  EXPECT_EQ(fix.nodesDropped, 3);  // f1, f2, f3
  EXPECT_EQ(fix.added.size(), 4u);
  SurfaceMesh after;
  after.nodes = m.nodes;
  after.nodeOn = m.nodeOn;
  for (const auto& t : fix.added) {
    EXPECT_NE(std::find(t.begin(), t.end(), hub), t.end());
    after.triangles.push_back(t);
    after.triangleFace.push_back(0);
  }
  expectUpward(after);
  EXPECT_EQ(countFoldedEdges(after), 0);
  EXPECT_EQ(rim(after), rim(m));
}
