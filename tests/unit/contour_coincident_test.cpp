// CoincidentEdges (surface/contour/CoincidentEdges.h): model vertices within their CAD
// tolerance share a representative; edges joining the same represented vertices along the
// same curve are twins; edges that only share their ends are not. Below the small-feature
// floor a face narrower than it collapses: its short edges to points, its long ones to twins.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "mesher/geometry/Circle3d.h"
#include "mesher/geometry/Line3d.h"
#include "mesher/surface/contour/CoincidentEdges.h"

namespace aniso {
namespace {

ModelEdge lineEdge(const Model& m, int v0, int v1) {
  ModelEdge e;
  e.v0 = v0;
  e.v1 = v1;
  e.curve = std::make_shared<Line3d>(m.vertices[v0].p, m.vertices[v1].p, 0.0, 1.0);
  e.t0 = 0;
  e.t1 = 1;
  e.tolerance = 1e-7;
  return e;
}

ModelVertex vertex(double x, double y, double z) { return {Vec3(x, y, z), 1e-7}; }

/// Two copies of the segment (0,0,0)-(1,0,0), each with its own end vertices (the second
/// pair 1e-9 away), plus a bent edge between the first pair's ends through (0.5, 0.3, 0).
Model twinModel() {
  Model m;
  m.vertices = {vertex(0, 0, 0), vertex(1, 0, 0), vertex(1e-9, 0, 0), vertex(1, 1e-9, 0), vertex(0.5, 0.3, 0)};
  m.edges.push_back(lineEdge(m, 0, 1));
  m.edges.push_back(lineEdge(m, 3, 2));  // the copy, running the other way
  m.edges.push_back(lineEdge(m, 0, 4));
  m.edges.push_back(lineEdge(m, 4, 1));
  return m;
}

TEST(CoincidentEdges, VerticesWithinToleranceShareOneRepresentative) {
  const Model m = twinModel();
  const std::vector<int> rep = contour::coincidentVertices(m, std::vector<char>(m.edges.size(), 1));
  EXPECT_EQ(rep, (std::vector<int>{0, 1, 0, 1, 4}));
}

TEST(CoincidentEdges, VerticesBeyondToleranceStayApart) {
  Model m = twinModel();
  m.vertices[2].p = Vec3(1e-6, 0, 0);  // 10x the tolerance
  const std::vector<int> rep = contour::coincidentVertices(m, std::vector<char>(m.edges.size(), 1));
  EXPECT_EQ(rep[2], 2);
  EXPECT_EQ(rep[3], 1);
}

TEST(CoincidentEdges, TheEndsOfOneEdgeAreNeverMerged) {
  Model m;
  m.vertices = {vertex(0, 0, 0), vertex(1e-9, 0, 0)};
  m.edges.push_back(lineEdge(m, 0, 1));
  const std::vector<int> rep = contour::coincidentVertices(m, {1});
  EXPECT_EQ(rep, (std::vector<int>{0, 1}));
}

TEST(CoincidentEdges, ACopyOfAnEdgeIsItsTwinAndAnotherPathIsNot) {
  const Model m = twinModel();
  const std::vector<char> used(m.edges.size(), 1);
  const std::vector<int> rep = contour::coincidentVertices(m, used);
  const contour::EdgeTwins twins = contour::coincidentEdges(m, used, rep);
  EXPECT_EQ(twins.count, 1);
  EXPECT_EQ(twins.of[1], 0);
  EXPECT_TRUE(twins.reversed[1]);
  EXPECT_EQ(twins.of[0], -1);
  EXPECT_EQ(twins.of[2], -1);
  EXPECT_EQ(twins.of[3], -1);
}

TEST(CoincidentEdges, SameEndsDifferentCurvesAreNotTwins) {
  Model m;
  m.vertices = {vertex(0, 0, 0), vertex(1, 0, 0)};
  m.edges.push_back(lineEdge(m, 0, 1));
  ModelEdge bent = lineEdge(m, 0, 1);
  // a curve leaving the segment in its middle: the segment of the first edge, moved 0.1 off
  bent.curve = std::make_shared<Line3d>(Vec3(0, 0.1, 0), Vec3(1, 0.1, 0), 0.0, 1.0);
  m.edges.push_back(bent);
  const std::vector<char> used(2, 1);
  const contour::EdgeTwins twins = contour::coincidentEdges(m, used, contour::coincidentVertices(m, used));
  EXPECT_EQ(twins.count, 0);
}

/// A face 2e-6 wide and 1 long (as KiCad's barrel jacks carry along an edge): vertices 0, 1
/// on one side, 3, 2 on the other; edges 0: 0→1, 1: 1→3 (short), 2: 3→2, 3: 2→0 (short).
Model stripModel() {
  Model m;
  m.vertices = {vertex(0, 0, 0), vertex(1, 0, 0), vertex(1, 2e-6, 0), vertex(0, 2e-6, 0)};
  m.edges = {lineEdge(m, 0, 1), lineEdge(m, 1, 2), lineEdge(m, 2, 3), lineEdge(m, 3, 0)};
  return m;
}

TEST(CoincidentEdges, AStripNarrowerThanTheFloorCollapses) {
  const Model m = stripModel();
  const std::vector<char> used(m.edges.size(), 1);
  const std::vector<int> rep = contour::coincidentVertices(m, used, 1e-5);
  EXPECT_EQ(rep, (std::vector<int>{0, 1, 1, 0}));
  EXPECT_TRUE(contour::collapsedEdge(m, 1, rep));
  EXPECT_TRUE(contour::collapsedEdge(m, 3, rep));
  EXPECT_FALSE(contour::collapsedEdge(m, 0, rep));
  const contour::EdgeTwins twins = contour::coincidentEdges(m, used, rep, 1e-5);
  EXPECT_EQ(twins.count, 1);
  EXPECT_EQ(twins.of[2], 0);
  EXPECT_TRUE(twins.reversed[2]);
  // without the floor (its CAD tolerances only) the strip stays
  const std::vector<int> tight = contour::coincidentVertices(m, used);
  EXPECT_EQ(tight, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(contour::coincidentEdges(m, used, tight).count, 0);
}

TEST(CoincidentEdges, ALongEdgeWhoseEndsAlmostMeetDoesNotCollapse) {
  // a circle of radius 1 open by 1e-6 (its ends within the floor, its length 2π is not)
  Model m;
  const double gap = 1e-6, kPi = std::acos(-1.0);
  m.vertices = {vertex(1, 0, 0), vertex(std::cos(2 * kPi - gap), std::sin(2 * kPi - gap), 0)};
  ModelEdge arc;
  arc.v0 = 0;
  arc.v1 = 1;
  arc.curve = std::make_shared<Circle3d>(Frame(), 1.0);
  arc.t0 = 0;
  arc.t1 = 2 * kPi - gap;
  m.edges.push_back(arc);
  const std::vector<int> rep = contour::coincidentVertices(m, {1}, 1e-5);
  EXPECT_EQ(rep, (std::vector<int>{0, 1}));
  EXPECT_FALSE(contour::collapsedEdge(m, 0, rep));
}

}  // namespace
}  // namespace aniso
