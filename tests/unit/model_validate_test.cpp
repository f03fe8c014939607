// Model::validate on small analytic models: a valid one passes, each kind of corruption is
// reported naming the entity by its 1-based id.
#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "mesher/geometry/Circle2d.h"
#include "mesher/geometry/Circle3d.h"
#include "mesher/geometry/CurveOnSurface3d.h"
#include "mesher/geometry/CylinderSurface.h"
#include "mesher/geometry/Line2d.h"
#include "mesher/geometry/Line3d.h"
#include "mesher/geometry/PlaneSurface.h"
#include "mesher/geometry/SphereSurface.h"
#include "mesher/model/Model.h"

using namespace aniso;

namespace {

constexpr double kPi = std::numbers::pi;

bool mentions(const std::vector<std::string>& msgs, const std::string& what) {
  for (const std::string& m : msgs)
    if (m.find(what) != std::string::npos) return true;
  return false;
}

std::string all(const std::vector<std::string>& msgs) {
  std::string s;
  for (const std::string& m : msgs) s += m + "\n";
  return s;
}

/// The unit square [0,1]² on the plane z = 0 as one face with four straight edges.
Model square() {
  Model m;
  const Vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const Vec2& p : uv) m.vertices.push_back({Vec3(p.x(), p.y(), 0), 1e-7});
  ModelFace f;
  f.surface = std::make_shared<PlaneSurface>(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 0, 1, 0, 1);
  f.uvBounds.add(Vec2(0, 0));
  f.uvBounds.add(Vec2(1, 1));
  Loop loop;
  loop.outer = true;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    ModelEdge e;
    e.v0 = i;
    e.v1 = j;
    e.t0 = 0;
    e.t1 = 1;
    e.curve = std::make_shared<Line3d>(m.vertices[i].p, m.vertices[j].p);
    e.pcurves.push_back({0, std::make_shared<Line2d>(uv[i], uv[j]), 0, 1, false});
    e.faces = {0};
    e.tolerance = 1e-7;
    m.edges.push_back(e);
    loop.uses.push_back({i, false, 0});
  }
  f.loops.push_back(loop);
  m.faces.push_back(f);
  m.shells.push_back({{{0, false}}, false});
  m.solids.push_back({"SOLID1", 0, {}});
  m.bbox.add(Vec3(0, 0, 0));
  m.bbox.add(Vec3(1, 1, 0));
  return m;
}

/// The full sphere face as OCCT builds it: a seam meridian used twice and two degenerate
/// edges at the poles.
Model sphere() {
  Model m;
  const double r = 2;
  auto s = std::make_shared<SphereSurface>(Frame(), r);
  m.vertices = {{Vec3(0, 0, -r), 1e-7}, {Vec3(0, 0, r), 1e-7}};
  ModelEdge seam;
  seam.v0 = 0; seam.v1 = 1; seam.t0 = 0; seam.t1 = 1; seam.seam = true; seam.faces = {0};
  seam.curve = std::make_shared<CurveOnSurface3d>(s, std::make_shared<Line2d>(Vec2(0, -kPi / 2), Vec2(0, kPi / 2)));
  seam.pcurves.push_back({0, std::make_shared<Line2d>(Vec2(2 * kPi, -kPi / 2), Vec2(2 * kPi, kPi / 2)), 0, 1, false});
  seam.pcurves.push_back({0, std::make_shared<Line2d>(Vec2(0, -kPi / 2), Vec2(0, kPi / 2)), 0, 1, true});
  ModelEdge south, north;
  south.v0 = south.v1 = 0; north.v0 = north.v1 = 1;
  south.degenerate = north.degenerate = true;
  south.t0 = north.t0 = 0; south.t1 = north.t1 = 1;
  south.faces = north.faces = {0};
  south.pcurves.push_back({0, std::make_shared<Line2d>(Vec2(0, -kPi / 2), Vec2(2 * kPi, -kPi / 2)), 0, 1, false});
  north.pcurves.push_back({0, std::make_shared<Line2d>(Vec2(0, kPi / 2), Vec2(2 * kPi, kPi / 2)), 0, 1, false});
  m.edges = {seam, south, north};
  ModelFace f;
  f.surface = s;
  f.uvBounds.add(Vec2(0, -kPi / 2));
  f.uvBounds.add(Vec2(2 * kPi, kPi / 2));
  // Counter-clockwise in (u,v): south pole, seam at 2π up, north pole back, seam at 0 down.
  f.loops.push_back({{{1, false, 0}, {0, false, 0}, {2, true, 0}, {0, true, 1}}, true});
  m.faces.push_back(f);
  m.shells.push_back({{{0, false}}, true});
  m.solids.push_back({"SOLID1", 0, {}});
  m.bbox.add(Vec3(-r, -r, -r));
  m.bbox.add(Vec3(r, r, r));
  return m;
}

}  // namespace

TEST(ModelValidate, ValidModelsPass) {
  EXPECT_TRUE(square().validate().empty()) << all(square().validate());
  EXPECT_TRUE(sphere().validate().empty()) << all(sphere().validate());
}

TEST(ModelValidate, CylinderWithHoleAndSeam) {
  // Lateral face of a cylinder (bottom circle, seam used twice, top circle) and a planar
  // cap on the bottom circle with a circular hole (inner loop, Circle2d pcurves).
  Model m;
  const double r = 1, h = 2;
  auto cyl = std::make_shared<CylinderSurface>(Frame(), r, 0, h);
  m.vertices = {{Vec3(r, 0, 0), 1e-7}, {Vec3(r, 0, h), 1e-7}};
  ModelEdge bottom, top, seam;
  bottom.v0 = bottom.v1 = 0; top.v0 = top.v1 = 1;
  bottom.t0 = top.t0 = 0; bottom.t1 = top.t1 = 2 * kPi;
  bottom.curve = std::make_shared<Circle3d>(Frame(), r);
  top.curve = std::make_shared<Circle3d>(Frame(Vec3(0, 0, h), Vec3::UnitZ()), r);
  bottom.pcurves.push_back({0, std::make_shared<Line2d>(Vec2(0, 0), Vec2(2 * kPi, 0), 0, 2 * kPi), 0, 2 * kPi, false});
  top.pcurves.push_back({0, std::make_shared<Line2d>(Vec2(0, h), Vec2(2 * kPi, h), 0, 2 * kPi), 0, 2 * kPi, false});
  bottom.faces = top.faces = {0};
  seam.v0 = 0; seam.v1 = 1; seam.t0 = 0; seam.t1 = h; seam.seam = true; seam.faces = {0};
  seam.curve = std::make_shared<Line3d>(Vec3(r, 0, 0), Vec3(r, 0, h), 0, h);
  seam.pcurves.push_back({0, std::make_shared<Line2d>(Vec2(2 * kPi, 0), Vec2(2 * kPi, h), 0, h), 0, h, false});
  seam.pcurves.push_back({0, std::make_shared<Line2d>(Vec2(0, 0), Vec2(0, h), 0, h), 0, h, true});
  // The bottom circle also bounds a planar cap (pcurve 2), which has a circular hole.
  bottom.faces = {0, 1};
  bottom.pcurves.push_back({1, std::make_shared<Circle2d>(Vec2(0, 0), r), 0, 2 * kPi, false});
  ModelEdge hole;
  m.vertices.push_back({Vec3(0.5, 0, 0), 1e-7});
  hole.v0 = hole.v1 = 2; hole.t0 = 0; hole.t1 = 2 * kPi; hole.faces = {1};
  hole.curve = std::make_shared<Circle3d>(Frame(), 0.5);
  hole.pcurves.push_back({1, std::make_shared<Circle2d>(Vec2(0, 0), 0.5), 0, 2 * kPi, false});
  m.edges = {bottom, top, seam, hole};
  ModelFace lateral;
  lateral.surface = cyl;
  lateral.uvBounds.add(Vec2(0, 0));
  lateral.uvBounds.add(Vec2(2 * kPi, h));
  lateral.loops.push_back({{{0, false, 0}, {2, false, 0}, {1, true, 0}, {2, true, 1}}, true});
  ModelFace cap;
  cap.surface = std::make_shared<PlaneSurface>(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), -r, r, -r, r);
  cap.uvBounds.add(Vec2(-r, -r));
  cap.uvBounds.add(Vec2(r, r));
  cap.loops.push_back({{{0, false, 1}}, true});
  cap.loops.push_back({{{3, true, 0}}, false});
  m.faces = {lateral, cap};
  m.bbox.add(Vec3(-r, -r, 0));
  m.bbox.add(Vec3(r, r, h));
  EXPECT_TRUE(m.validate().empty()) << all(m.validate());

  Model noSecond = m;
  noSecond.edges[2].pcurves[1].seamSecond = false;
  EXPECT_TRUE(mentions(noSecond.validate(), "edge 3: seam on face 1")) << all(noSecond.validate());

  Model notSeam = m;
  notSeam.edges[2].seam = false;
  EXPECT_TRUE(mentions(notSeam.validate(), "not marked seam"));

  // Using the same seam pcurve twice leaves the loop open by a full period in u.
  Model samePcurve = m;
  samePcurve.faces[0].loops[0].uses[3].pcurve = 0;
  EXPECT_TRUE(mentions(samePcurve.validate(), "face 1 loop 1 between uses 3 and 4: open")) << all(samePcurve.validate());

  Model twoOuter = m;
  twoOuter.faces[1].loops[1].outer = true;
  EXPECT_TRUE(mentions(twoOuter.validate(), "face 2 loop 2: a second outer loop"));
}

TEST(ModelValidate, ReferencesOutOfRange) {
  Model m = square();
  m.edges[1].v1 = 7;
  m.faces[0].loops[0].uses[2].edge = 9;
  m.shells[0].faces[0].face = 3;
  m.solids[0].outerShell = 2;
  const auto msgs = m.validate();
  EXPECT_TRUE(mentions(msgs, "edge 2: vertex reference out of range")) << all(msgs);
  EXPECT_TRUE(mentions(msgs, "face 1 loop 1 use 3: edge reference out of range")) << all(msgs);
  EXPECT_TRUE(mentions(msgs, "shell 1: face reference out of range")) << all(msgs);
  EXPECT_TRUE(mentions(msgs, "solid 1: outer shell reference out of range")) << all(msgs);
}

TEST(ModelValidate, MissingPcurvesAndCurves) {
  Model m = square();
  m.edges[0].pcurves.clear();
  m.edges[3].curve = nullptr;
  const auto msgs = m.validate();
  EXPECT_TRUE(mentions(msgs, "edge 1: no pcurve on face 1")) << all(msgs);
  EXPECT_TRUE(mentions(msgs, "face 1 loop 1 use 1: edge 1 has no pcurve 1")) << all(msgs);
  EXPECT_TRUE(mentions(msgs, "edge 4: no 3D curve")) << all(msgs);

  Model unlisted = square();
  unlisted.edges[2].faces = {};
  EXPECT_TRUE(mentions(unlisted.validate(), "edge 3 pcurve 1: face 1 is not listed")) << all(unlisted.validate());
  EXPECT_TRUE(mentions(unlisted.validate(), "use 3: edge 3 does not list this face"));
}

TEST(ModelValidate, OpenLoopsAndMisplacedCurves) {
  // A pcurve that does not end where the next starts.
  Model m = square();
  m.edges[1].pcurves[0].curve = std::make_shared<Line2d>(Vec2(1, 0), Vec2(1, 0.9));
  auto msgs = m.validate();
  EXPECT_TRUE(mentions(msgs, "face 1 loop 1 between uses 2 and 3: open")) << all(msgs);
  EXPECT_TRUE(mentions(msgs, "edge 2 pcurve 1 on face 1: end is")) << all(msgs);

  // A tiny gap within tolerance is accepted.
  Model tiny = square();
  tiny.edges[1].pcurves[0].curve = std::make_shared<Line2d>(Vec2(1, 0), Vec2(1, 1 - 1e-9));
  EXPECT_TRUE(tiny.validate().empty()) << all(tiny.validate());

  // Uses that do not chain vertex to vertex.
  Model flipped = square();
  flipped.faces[0].loops[0].uses[1].reversed = true;
  EXPECT_TRUE(mentions(flipped.validate(), "between uses 1 and 2: vertex 2 does not chain to vertex 3"))
      << all(flipped.validate());

  // A 3D curve away from its vertex.
  Model moved = square();
  moved.edges[0].curve = std::make_shared<Line3d>(Vec3(0, 0, 0.01), Vec3(1, 0, 0));
  EXPECT_TRUE(mentions(moved.validate(), "edge 1 3D curve: start is")) << all(moved.validate());
}

TEST(ModelValidate, PoleGapWithoutDegenerateEdges) {
  // Dropping the degenerate edges leaves gaps of 2π in u at the poles: 0 in 3D, but not
  // closed in the parametric plane.
  Model m = sphere();
  m.faces[0].loops[0].uses = {{0, false, 0}, {0, true, 1}};
  const auto msgs = m.validate();
  EXPECT_TRUE(mentions(msgs, "face 1 loop 1 between uses 1 and 2: open by (6.28, 0)")) << all(msgs);
  EXPECT_TRUE(mentions(msgs, "face 1 loop 1 between uses 2 and 1: open")) << all(msgs);
}

TEST(ModelValidate, ClosedShellNeedsTwoUsesPerEdge) {
  Model m = square();
  m.shells[0].closed = true;
  const auto msgs = m.validate();
  EXPECT_EQ(msgs.size(), 4u) << all(msgs);
  EXPECT_TRUE(mentions(msgs, "shell 1: closed, but edge 1 is used 1 times"));
}
