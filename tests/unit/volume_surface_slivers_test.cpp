// mendSurfaceSlivers (mesher/volume/SurfaceSlivers.h): caps and sub-tolerance edges of a
// closed surface removed before the volume, on a hand-made shell — the top of a box split
// into two faces by a strip face 1e-6 wide whose two rims have staggered nodes (the tip of
// a fillet), closed below by a pyramid. After each call: SurfaceMesh::validate(), closed,
// oriented, manifold, enclosed volume kept.
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "mesher/volume/SurfaceSlivers.h"

using namespace aniso;

namespace {

constexpr double kStrip = 1e-6;

NodeOn on(NodeOn::Kind kind, int entity) { return NodeOn{kind, entity, 0, Vec2(0, 0)}; }

/// Triangles (counter-clockwise from +z) between two rows of nodes sorted by x, on `face`.
void zipRows(SurfaceMesh& m, const std::vector<int>& lo, const std::vector<int>& hi, int face) {
  std::size_t i = 0, j = 0;
  while (i + 1 < lo.size() || j + 1 < hi.size()) {
    const bool advanceLo =
        j + 1 >= hi.size() || (i + 1 < lo.size() && m.nodes[lo[i + 1]].x() <= m.nodes[hi[j + 1]].x());
    if (advanceLo) {
      m.triangles.push_back({lo[i], lo[i + 1], hi[j]});
      ++i;
    } else {
      m.triangles.push_back({lo[i], hi[j + 1], hi[j]});
      ++j;
    }
    m.triangleFace.push_back(face);
  }
}

/// Directed edges used once (the rim of an open mesh).
std::vector<std::pair<int, int>> rim(const SurfaceMesh& m) {
  std::map<std::pair<int, int>, int> net;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a < b)
        ++net[{a, b}];
      else
        --net[{b, a}];
    }
  std::vector<std::pair<int, int>> out;
  for (const auto& [e, n] : net)
    if (n == 1)
      out.push_back(e);
    else if (n == -1)
      out.push_back({e.second, e.first});
  return out;
}

/// The shell: rows y = 0, 0.5, 0.5 + kStrip, 1 at z = 0 (faces 0 | strip 2 | 1; the strip's
/// rims are CAD edges 0 and 1 with staggered nodes; the corners are CAD vertices), closed
/// by triangles to an apex below (face 3). `stripRows` false: no strip (a plain seam).
SurfaceMesh stripShell(bool stripRows = true) {
  SurfaceMesh m;
  const auto row = [&](double y, const std::vector<double>& xs, NodeOn::Kind kind, int entity, bool corners) {
    std::vector<int> ids;
    for (std::size_t k = 0; k < xs.size(); ++k) {
      const bool end = k == 0 || k + 1 == xs.size();
      ids.push_back(m.addNode(Vec3(xs[k], y, 0), corners && end ? on(NodeOn::Kind::Vertex, static_cast<int>(k)) : on(kind, entity)));
    }
    return ids;
  };
  const auto r0 = row(0, {0, 0.5, 1}, NodeOn::Kind::Face, 0, true);
  const auto r1 = row(0.5, {0, 0.2, 0.4, 0.6, 0.8, 1}, NodeOn::Kind::Edge, 0, false);
  const auto r3 = row(1, {0, 0.5, 1}, NodeOn::Kind::Face, 1, true);
  zipRows(m, r0, r1, 0);
  if (stripRows) {
    const auto r2 = row(0.5 + kStrip, {0, 0.1, 0.3, 0.5, 0.7, 0.9, 1}, NodeOn::Kind::Edge, 1, false);
    zipRows(m, r1, r2, 2);
    zipRows(m, r2, r3, 1);
  } else {
    zipRows(m, r1, r3, 1);
  }
  const int apex = m.addNode(Vec3(0.5, 0.5, -1), on(NodeOn::Kind::Face, 3));
  for (const auto& [a, b] : rim(m)) {
    m.triangles.push_back({b, a, apex});
    m.triangleFace.push_back(3);
  }
  return m;
}

double enclosedVolume(const SurfaceMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += m.nodes[t[0]].dot(m.nodes[t[1]].cross(m.nodes[t[2]])) / 6;
  return v;
}

double shortestEdge(const SurfaceMesh& m) {
  double s = 1e300;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) s = std::min(s, (m.nodes[t[k]] - m.nodes[t[(k + 1) % 3]]).norm());
  return s;
}

void expectClosedAndValid(const SurfaceMesh& m) {
  EXPECT_TRUE(m.validate().empty()) << m.validate().front();
  const SurfaceMesh::EdgeCounts c = m.edgeCounts();
  EXPECT_EQ(c.open, 0);
  EXPECT_EQ(c.nonManifold, 0);
  EXPECT_EQ(c.misoriented, 0);
}

}  // namespace

TEST(SurfaceSlivers, StripOfCapsAndShortEdgesIsMendedKeepingTheShellClosed) {
  SurfaceMesh m = stripShell();
  expectClosedAndValid(m);
  ASSERT_GT(countSurfaceCaps(m), 0);
  ASSERT_LT(shortestEdge(m), 1e-5);
  const double volume = enclosedVolume(m);
  const std::size_t nodes = m.nodes.size();
  const SurfaceSliverStats s = mendSurfaceSlivers(m, 1e-4);
  expectClosedAndValid(m);
  EXPECT_EQ(countSurfaceCaps(m), 0);
  EXPECT_GT(shortestEdge(m), 1e-4);
  EXPECT_GT(s.capsFlipped, 0);
  EXPECT_GT(s.nodesMerged, 0);  // the strip's ends: two edge nodes 1e-6 apart
  EXPECT_NEAR(enclosedVolume(m), volume, 1e-6);
  EXPECT_EQ(m.nodes.size(), nodes);  // merged nodes stay in the node array
}

TEST(SurfaceSlivers, CadVerticesAreNotMergedIntoEdgeOrFaceNodes) {
  SurfaceMesh m = stripShell();
  std::vector<int> vertices;
  for (int v = 0; v < static_cast<int>(m.nodes.size()); ++v)
    if (m.nodeOn[v].kind == NodeOn::Kind::Vertex) vertices.push_back(v);
  mendSurfaceSlivers(m, 1e-4);
  std::vector<int> used(m.nodes.size(), 0);
  for (const auto& t : m.triangles)
    for (const int v : t) used[v] = 1;
  for (const int v : vertices) EXPECT_TRUE(used[v]) << v;
}

TEST(SurfaceSlivers, ACadEdgeShorterThanTheToleranceVanishesIntoOneVertex) {
  // the strip's rims end at CAD vertices: its two ends are CAD edges 1e-6 long between two
  // vertex nodes, which no tet holding them survives; each pair becomes one node
  SurfaceMesh m = stripShell();
  std::vector<int> ends;
  for (int v = 0; v < static_cast<int>(m.nodes.size()); ++v)
    if (m.nodeOn[v].kind == NodeOn::Kind::Edge && (m.nodes[v].x() == 0 || m.nodes[v].x() == 1)) {
      m.nodeOn[v] = on(NodeOn::Kind::Vertex, 10 + v);
      ends.push_back(v);
    }
  ASSERT_EQ(ends.size(), 4u);
  const double volume = enclosedVolume(m);
  mendSurfaceSlivers(m, 1e-4);
  expectClosedAndValid(m);
  EXPECT_GT(shortestEdge(m), 1e-4);
  EXPECT_NEAR(enclosedVolume(m), volume, 1e-6);
  std::vector<int> used(m.nodes.size(), 0);
  for (const auto& t : m.triangles)
    for (const int v : t) used[v] = 1;
  EXPECT_EQ(std::count_if(ends.begin(), ends.end(), [&](int v) { return used[v]; }), 2);
}

TEST(SurfaceSlivers, LeavesAMeshWithoutSliversAsItIs) {
  SurfaceMesh m = stripShell(false);
  ASSERT_EQ(countSurfaceCaps(m), 0);
  const auto before = m.triangles;
  const SurfaceSliverStats s = mendSurfaceSlivers(m, 1e-4);
  EXPECT_EQ(s.capsFlipped + s.nodesMerged, 0);
  EXPECT_EQ(m.triangles, before);
}

/// The strip's upper rim (CAD edge 1) raised to z.
SurfaceMesh raisedStrip(double z) {
  SurfaceMesh m = stripShell();
  for (int v = 0; v < static_cast<int>(m.nodes.size()); ++v)
    if (m.nodeOn[v].kind == NodeOn::Kind::Edge && m.nodeOn[v].entity == 1) m.nodes[v].z() = z;
  return m;
}

TEST(SurfaceSlivers, ACapOffThePlaneBeyondTheToleranceStays) {
  // the strip raised: its upper rim above the others' plane beyond a 1e-4 tolerance and
  // beyond the local one (kLocalSliverRatio of the caps' long edges, 0.2 at most), the nodes
  // farther apart than either: no strip cap goes across a rim (the raised strip's ends make
  // caps of the pyramid's long triangles, which may flip among themselves)
  SurfaceMesh m = raisedStrip(2 * kLocalSliverRatio * 0.2);
  ASSERT_GT(countSurfaceCaps(m), 0);
  const auto onFace = [&](int f) { return std::count(m.triangleFace.begin(), m.triangleFace.end(), f); };
  const auto top = std::array{onFace(0), onFace(1), onFace(2)};
  mendSurfaceSlivers(m, 1e-4);
  expectClosedAndValid(m);
  EXPECT_EQ(top, (std::array{onFace(0), onFace(1), onFace(2)}));
  EXPECT_GT(countSurfaceCaps(m), 0);  // flips inside the strip's plane may take some
}

TEST(SurfaceSlivers, ACapOffThePlaneWithinTheLocalToleranceIsFlipped) {
  // the rim raised by less than kLocalSliverRatio of the caps' long edges (0.1 at least) but
  // far beyond the 1e-4 tolerance: the caps are the CAD's, below the local size
  SurfaceMesh m = raisedStrip(0.5 * kLocalSliverRatio * 0.1);
  const int caps = countSurfaceCaps(m);
  ASSERT_GT(caps, 0);
  const SurfaceSliverStats s = mendSurfaceSlivers(m, 1e-4);
  expectClosedAndValid(m);
  EXPECT_GT(s.capsFlipped, 0);
  EXPECT_LT(countSurfaceCaps(m), caps);
}

TEST(SurfaceSlivers, NodesFromKeepFromOnAreNeverMergedAway) {
  // The recovery's boundary splits add nodes at the end of the node array; a merge that
  // removed them would undo the split, and the same entity would go missing again round
  // after round. With keepFrom at the strip's second rim, no node of it leaves the mesh.
  SurfaceMesh m = stripShell();
  int firstOfRim2 = -1;
  for (int v = 0; v < static_cast<int>(m.nodes.size()); ++v)
    if (firstOfRim2 < 0 && m.nodeOn[v].kind == NodeOn::Kind::Edge && m.nodeOn[v].entity == 1) firstOfRim2 = v;
  ASSERT_GT(firstOfRim2, 0);
  const auto usedFrom = [&](const SurfaceMesh& mesh, int from) {
    std::vector<int> used(mesh.nodes.size(), 0);
    for (const auto& t : mesh.triangles)
      for (const int v : t) used[v] = 1;
    int n = 0;
    for (int v = from; v < static_cast<int>(mesh.nodes.size()); ++v) n += used[v];
    return n;
  };
  const int before = usedFrom(m, firstOfRim2);
  SurfaceMesh free = m;
  mendSurfaceSlivers(free, 1e-4);
  EXPECT_LT(usedFrom(free, firstOfRim2), before);  // without: the strip's ends merge away
  const double volume = enclosedVolume(m);
  mendSurfaceSlivers(m, 1e-4, nullptr, firstOfRim2);
  expectClosedAndValid(m);
  EXPECT_EQ(usedFrom(m, firstOfRim2), before);
  EXPECT_NEAR(enclosedVolume(m), volume, 1e-6);
}
