// buildTopology on primitives, a solid with a cavity, compounds, moved and reversed shapes
// and two public BREP models: counts, seams, poles, closed loops, orientation conventions,
// shell closedness, and Model::validate().
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_Circle.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Line.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Wire.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pln.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cad/TopologyBuilder.h"
#include "occt_test_util.h"

namespace aniso::cad {
namespace {

using test::kPi;

Model build(const TopoDS_Shape& shape) {
  return buildTopology(shape, [](const TopoDS_Shape&, int id) {
    std::string name = "S";
    return name += std::to_string(id);
  });
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += x + "\n";
  return s;
}

const PCurve& pcurveOf(const Model& m, const EdgeUse& u) {
  return m.edges[u.edge].pcurves[u.pcurve];
}
Vec2 useStart(const Model& m, const EdgeUse& u) {
  const PCurve& pc = pcurveOf(m, u);
  return pc.curve->point(u.reversed ? pc.t1 : pc.t0);
}
Vec2 useEnd(const Model& m, const EdgeUse& u) {
  const PCurve& pc = pcurveOf(m, u);
  return pc.curve->point(u.reversed ? pc.t0 : pc.t1);
}
int startVertex(const Model& m, const EdgeUse& u) {
  return u.reversed ? m.edges[u.edge].v1 : m.edges[u.edge].v0;
}
int endVertex(const Model& m, const EdgeUse& u) {
  return u.reversed ? m.edges[u.edge].v0 : m.edges[u.edge].v1;
}

/// How far the checks below let geometry be off: `abs` (model units, or (u,v) units for
/// loop gaps) plus `cadFactor` × the CAD tolerances involved, plus `uvRel` × the face's
/// (u,v) extent for loop gaps. Primitives are exact; files carry their tolerances.
struct Slack {
  double abs = 1e-7;
  double cadFactor = 0;
  double uvRel = 0;
};
const Slack kExact;

/// Every loop is a closed chain of vertices and closed in (u,v); uses name pcurves of
/// their own face.
void expectLoopsClosed(const Model& m, const Slack& slack) {
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (const Loop& loop : m.faces[f].loops) {
      SCOPED_TRACE("face " + std::to_string(f + 1));
      const double tol = slack.abs + slack.uvRel * m.faces[f].uvBounds.diagonal();
      ASSERT_FALSE(loop.uses.empty());
      for (std::size_t k = 0; k < loop.uses.size(); ++k) {
        const EdgeUse& a = loop.uses[k];
        const EdgeUse& b = loop.uses[(k + 1) % loop.uses.size()];
        EXPECT_EQ(pcurveOf(m, a).face, static_cast<int>(f));
        EXPECT_EQ(endVertex(m, a), startVertex(m, b));
        EXPECT_LT((useEnd(m, a) - useStart(m, b)).norm(), tol)
            << "between edge " << a.edge + 1 << " and edge " << b.edge + 1;
      }
    }
}

/// Signed area of a loop in (u,v), walked as the uses say.
double signedArea(const Model& m, const Loop& loop) {
  std::vector<Vec2> poly;
  for (const EdgeUse& u : loop.uses) {
    const PCurve& pc = pcurveOf(m, u);
    for (int i = 0; i < 64; ++i) {
      const double s = u.reversed ? 1.0 - i / 64.0 : i / 64.0;
      poly.push_back(pc.curve->point(pc.t0 + s * (pc.t1 - pc.t0)));
    }
  }
  double a = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % poly.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

/// The EdgeUse convention: the face on the left in (u,v) for a non-reversed face (outer loop
/// counter-clockwise), on the right for a reversed one.
void expectLoopOrientation(const Model& m) {
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const double sign = m.faces[f].reversed ? -1 : 1;
    for (const Loop& loop : m.faces[f].loops) {
      const double a = sign * signedArea(m, loop);
      if (loop.outer)
        EXPECT_GT(a, 0) << "face " << f + 1 << " outer loop";
      else
        EXPECT_LT(a, 0) << "face " << f + 1 << " inner loop";
    }
  }
}

/// SameParameter: the pcurve on the surface is the 3D curve; edge ends are its vertices.
void expectGeometryConsistent(const Model& m, const Slack& slack) {
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    SCOPED_TRACE("edge " + std::to_string(e + 1));
    const ModelEdge& me = m.edges[e];
    double cad = std::max({me.tolerance, m.vertices[me.v0].tolerance, m.vertices[me.v1].tolerance});
    for (const PCurve& pc : me.pcurves) cad = std::max(cad, m.faces[pc.face].tolerance);
    const double tol = slack.abs + slack.cadFactor * cad;
    EXPECT_EQ(me.degenerate, me.curve == nullptr);
    if (me.curve) {
      EXPECT_LT((me.curve->point(me.t0) - m.vertices[me.v0].p).norm(), tol);
      EXPECT_LT((me.curve->point(me.t1) - m.vertices[me.v1].p).norm(), tol);
    } else {
      EXPECT_EQ(me.v0, me.v1);
    }
    for (const PCurve& pc : me.pcurves)
      for (int i = 0; i <= 4; ++i) {
        const double t = pc.t0 + (pc.t1 - pc.t0) * i / 4;
        const Vec3 on = m.faces[pc.face].surface->point(pc.curve->point(t));
        const Vec3 want = me.curve ? me.curve->point(t) : m.vertices[me.v0].p;
        EXPECT_LT((on - want).norm(), tol) << "on face " << pc.face + 1 << " at t = " << t;
      }
  }
}

/// In a closed shell every counted edge is walked once each way (face orientations in the
/// shell taken into account).
void expectShellEdgesOpposed(const Model& m, int shell) {
  std::vector<int> count(m.edges.size(), 0), sum(m.edges.size(), 0);
  for (const FaceUse& fu : m.shells[shell].faces) {
    const bool flip = fu.reversed != m.faces[fu.face].reversed;
    for (const Loop& loop : m.faces[fu.face].loops)
      for (const EdgeUse& u : loop.uses) {
        if (m.edges[u.edge].seam || m.edges[u.edge].degenerate) continue;
        ++count[u.edge];
        sum[u.edge] += (u.reversed != flip) ? -1 : 1;
      }
  }
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    if (count[e] == 0) continue;
    EXPECT_EQ(count[e], 2) << "edge " << e + 1;
    EXPECT_EQ(sum[e], 0) << "edge " << e + 1;
  }
}

/// The shell's oriented normals point away from `center` (sign +1) or towards it (−1):
/// checked at the middle of each face's (u,v) bounds (convex primitives only).
void expectNormalsFrom(const Model& m, int shell, const Vec3& center, double sign) {
  for (const FaceUse& fu : m.shells[shell].faces) {
    const ModelFace& f = m.faces[fu.face];
    const Vec2 uv = 0.5 * (f.uvBounds.lo + f.uvBounds.hi);
    const Vec3 n = f.surface->normal(uv) * (fu.reversed ? -1.0 : 1.0);
    EXPECT_GT(sign * n.dot(f.surface->point(uv) - center), 0) << "face " << fu.face + 1;
  }
}

void expectSound(const Model& m, const Slack& slack = kExact) {
  EXPECT_TRUE(m.validate().empty()) << joined(m.validate());
  expectLoopsClosed(m, slack);
  expectLoopOrientation(m);
  expectGeometryConsistent(m, slack);
  for (std::size_t s = 0; s < m.shells.size(); ++s)
    if (m.shells[s].closed) expectShellEdgesOpposed(m, static_cast<int>(s));
}

TEST(BuildTopology, Box) {
  const Model m = build(BRepPrimAPI_MakeBox(gp_Pnt(1, 2, 3), 2, 3, 4).Shape());
  ASSERT_EQ(m.vertices.size(), 8u);
  ASSERT_EQ(m.edges.size(), 12u);
  ASSERT_EQ(m.faces.size(), 6u);
  ASSERT_EQ(m.shells.size(), 1u);
  ASSERT_EQ(m.solids.size(), 1u);
  EXPECT_TRUE(m.shells[0].closed);
  EXPECT_EQ(m.shells[0].faces.size(), 6u);
  EXPECT_EQ(m.solids[0].outerShell, 0);
  EXPECT_TRUE(m.solids[0].voidShells.empty());
  EXPECT_EQ(m.solids[0].name, "S1");
  for (const ModelFace& f : m.faces) {
    ASSERT_EQ(f.loops.size(), 1u);
    EXPECT_TRUE(f.loops[0].outer);
    EXPECT_EQ(f.loops[0].uses.size(), 4u);
  }
  for (const ModelEdge& e : m.edges) {
    EXPECT_FALSE(e.seam || e.degenerate);
    EXPECT_EQ(e.faces.size(), 2u);
    EXPECT_EQ(e.pcurves.size(), 2u);
    EXPECT_NE(e.v0, e.v1);
  }
  EXPECT_LT((m.bbox.lo - Vec3(1, 2, 3)).norm(), 1e-6);
  EXPECT_LT((m.bbox.hi - Vec3(3, 5, 7)).norm(), 1e-6);
  expectSound(m);
  expectNormalsFrom(m, 0, Vec3(2, 3.5, 5), 1);
}

TEST(BuildTopology, CylinderSeamHasTwoPcurvesOnTheLateralFace) {
  const Model m = build(BRepPrimAPI_MakeCylinder(1.5, 3.0).Shape());
  ASSERT_EQ(m.faces.size(), 3u);
  ASSERT_EQ(m.edges.size(), 3u);
  ASSERT_EQ(m.vertices.size(), 2u);
  int seams = 0;
  for (std::size_t e = 0; e < m.edges.size(); ++e) {
    const ModelEdge& me = m.edges[e];
    if (!me.seam) {
      EXPECT_EQ(me.faces.size(), 2u);  // a circle: lateral face and a cap
      continue;
    }
    ++seams;
    ASSERT_EQ(me.faces.size(), 1u);
    ASSERT_EQ(me.pcurves.size(), 2u);
    EXPECT_EQ(me.pcurves[0].face, me.pcurves[1].face);
    EXPECT_NE(me.pcurves[0].seamSecond, me.pcurves[1].seamSecond);
    // The lateral loop walks the seam once each way, on different pcurves.
    const Loop& loop = m.faces[me.faces[0]].loops.at(0);
    std::vector<const EdgeUse*> uses;
    for (const EdgeUse& u : loop.uses)
      if (u.edge == static_cast<int>(e)) uses.push_back(&u);
    ASSERT_EQ(uses.size(), 2u);
    EXPECT_NE(uses[0]->reversed, uses[1]->reversed);
    EXPECT_NE(uses[0]->pcurve, uses[1]->pcurve);
    const Vec2 a = me.pcurves[0].curve->point(me.t0), b = me.pcurves[1].curve->point(me.t0);
    EXPECT_NEAR(std::abs(a.x() - b.x()), 2 * kPi, 1e-9);
  }
  EXPECT_EQ(seams, 1);
  EXPECT_TRUE(m.shells.at(0).closed);
  expectSound(m);
  expectNormalsFrom(m, 0, Vec3(0, 0, 1.5), 1);
}

// A face of revolution as OCCT's STEP translation delivered the peg tips of KiCad battery
// holders, on a cylinder (radius 1, height 2): its loop runs the top circle from u = 0 to
// -2π, the seam at -2π, the bottom circle from 0 to 2π, the seam at 2π, and closes the two
// jumps of 2π with two "degenerated" edges whose pcurves run a whole circle each (no pole:
// the surface there is the circle, not a point). The mesher's loop leaves them out and
// keeps the four real uses; chained across the jumps by whole periods, the boundary is
// one rectangle of width 2π, not two overlapping ones.
TEST(BuildTopology, FalsePolesBridgingPeriodJumpsAreLeftOut) {
  const double h = 2, tol = 1e-7;
  BRep_Builder b;
  Handle(Geom_CylindricalSurface) cyl = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), 1.0);
  TopoDS_Face face;
  b.MakeFace(face, cyl, tol);
  TopoDS_Vertex vb, vt;
  b.MakeVertex(vb, gp_Pnt(1, 0, 0), tol);
  b.MakeVertex(vt, gp_Pnt(1, 0, h), tol);
  const auto closedEdge = [&](const TopoDS_Vertex& v) {
    TopoDS_Edge e;
    b.MakeEdge(e);
    b.Add(e, v.Oriented(TopAbs_FORWARD));
    b.Add(e, v.Oriented(TopAbs_REVERSED));
    return e;
  };
  const auto line = [](double u, double v, double du, double dv) {
    return Handle(Geom2d_Line)(new Geom2d_Line(gp_Pnt2d(u, v), gp_Dir2d(du, dv)));
  };
  // top circle, walked reversed: t in [0, 2π] is u = t - 2π
  TopoDS_Edge top = closedEdge(vt);
  b.UpdateEdge(top, new Geom_Circle(gp_Ax2(gp_Pnt(0, 0, h), gp::DZ()), 1.0), tol);
  b.UpdateEdge(top, line(-2 * kPi, h, 1, 0), face, tol);
  b.Range(top, 0, 2 * kPi);
  // bottom circle, walked forward: u = t
  TopoDS_Edge bottom = closedEdge(vb);
  b.UpdateEdge(bottom, new Geom_Circle(gp::XOY(), 1.0), tol);
  b.UpdateEdge(bottom, line(0, 0, 1, 0), face, tol);
  b.Range(bottom, 0, 2 * kPi);
  // seam: forward at u = 2π (up), reversed at u = -2π (down)
  TopoDS_Edge seam;
  b.MakeEdge(seam, new Geom_Line(gp_Pnt(1, 0, 0), gp::DZ()), tol);
  b.Add(seam, vb.Oriented(TopAbs_FORWARD));
  b.Add(seam, vt.Oriented(TopAbs_REVERSED));
  b.UpdateEdge(seam, line(2 * kPi, 0, 0, 1), line(-2 * kPi, 0, 0, 1), face, tol);
  b.Range(seam, 0, h);
  // the two false poles: (2π, h) -> (0, h) at the top vertex, (-2π, 0) -> (0, 0) at the bottom one
  const auto falsePole = [&](const TopoDS_Vertex& v, double u, double vv, double du) {
    TopoDS_Edge e = closedEdge(v);
    b.UpdateEdge(e, line(u, vv, du, 0), face, tol);
    b.Range(e, 0, 2 * kPi);
    b.Degenerated(e, true);
    return e;
  };
  const TopoDS_Edge d1 = falsePole(vt, 2 * kPi, h, -1), d2 = falsePole(vb, -2 * kPi, 0, 1);
  TopoDS_Wire wire;
  b.MakeWire(wire);
  b.Add(wire, d1);
  b.Add(wire, top.Reversed());
  b.Add(wire, seam.Reversed());
  b.Add(wire, d2);
  b.Add(wire, bottom);
  b.Add(wire, seam);
  b.Add(face, wire);

  const Model m = build(face);
  ASSERT_EQ(m.faces.size(), 1u);
  ASSERT_EQ(m.faces[0].loops.size(), 1u);
  const Loop& loop = m.faces[0].loops[0];
  ASSERT_EQ(loop.uses.size(), 4u);  // top, seam, bottom, seam
  for (const EdgeUse& u : loop.uses) EXPECT_FALSE(m.edges[static_cast<std::size_t>(u.edge)].degenerate);
  // the two jumps are whole periods, closed in 3D: Defects the face mesher chains across
  const std::vector<ModelIssue> issues = m.check();
  EXPECT_EQ(issues.size(), 2u) << joined(m.validate());
  for (const ModelIssue& i : issues) {
    EXPECT_EQ(i.level, ModelIssue::Level::Defect) << i.message;
    EXPECT_LT(i.uvGapShare, 1e-9) << i.message;
  }
}

TEST(BuildTopology, SphereHasDegenerateEdgesAtThePoles) {
  const double r = 2.0;
  const Model m = build(BRepPrimAPI_MakeSphere(r).Shape());
  ASSERT_EQ(m.faces.size(), 1u);
  ASSERT_EQ(m.edges.size(), 3u);
  ASSERT_EQ(m.vertices.size(), 2u);
  int degenerate = 0, seams = 0;
  for (const ModelEdge& e : m.edges) {
    if (e.degenerate) {
      ++degenerate;
      EXPECT_EQ(e.curve, nullptr);
      EXPECT_EQ(e.v0, e.v1);
      EXPECT_NEAR(std::abs(m.vertices[e.v0].p.z()), r, 1e-9);
      EXPECT_NEAR(m.vertices[e.v0].p.head<2>().norm(), 0, 1e-9);
      EXPECT_EQ(e.pcurves.size(), 1u);
    }
    if (e.seam) ++seams;
  }
  EXPECT_EQ(degenerate, 2);
  EXPECT_EQ(seams, 1);
  EXPECT_EQ(m.faces[0].loops.at(0).uses.size(), 4u);
  EXPECT_TRUE(m.shells.at(0).closed);
  EXPECT_NEAR(m.faces[0].uvBounds.lo.y(), -kPi / 2, 1e-9);
  EXPECT_NEAR(m.faces[0].uvBounds.hi.y(), kPi / 2, 1e-9);
  EXPECT_LT((m.bbox.hi - Vec3(r, r, r)).norm(), 1e-6);
  expectSound(m);
  expectNormalsFrom(m, 0, Vec3::Zero(), 1);
}

TEST(BuildTopology, TorusAndCone) {
  const Model torus = build(BRepPrimAPI_MakeTorus(3.0, 1.0).Shape());
  ASSERT_EQ(torus.faces.size(), 1u);
  ASSERT_EQ(torus.edges.size(), 2u);
  ASSERT_EQ(torus.vertices.size(), 1u);
  for (const ModelEdge& e : torus.edges) {
    EXPECT_TRUE(e.seam);
    EXPECT_EQ(e.pcurves.size(), 2u);
  }
  EXPECT_EQ(torus.faces[0].loops.at(0).uses.size(), 4u);
  expectSound(torus);

  const Model cone = build(BRepPrimAPI_MakeCone(2.0, 0.0, 3.0).Shape());
  ASSERT_EQ(cone.faces.size(), 2u);
  ASSERT_EQ(cone.edges.size(), 3u);
  ASSERT_EQ(cone.vertices.size(), 2u);
  int degenerate = 0;
  for (const ModelEdge& e : cone.edges) degenerate += e.degenerate;
  EXPECT_EQ(degenerate, 1);  // the apex
  EXPECT_TRUE(cone.shells.at(0).closed);
  expectSound(cone);
  expectNormalsFrom(cone, 0, Vec3(0, 0, 1), 1);
}

TEST(BuildTopology, SolidWithACavity) {
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 10, 10).Shape();
  const TopoDS_Shape ball = BRepPrimAPI_MakeSphere(gp_Pnt(5, 5, 5), 2).Shape();
  BRepAlgoAPI_Cut cut(box, ball);
  ASSERT_TRUE(cut.IsDone());
  const Model m = build(cut.Shape());
  ASSERT_EQ(m.solids.size(), 1u);
  ASSERT_EQ(m.shells.size(), 2u);
  const ModelSolid& s = m.solids[0];
  ASSERT_EQ(s.voidShells.size(), 1u);
  EXPECT_EQ(m.shells[s.outerShell].faces.size(), 6u);
  EXPECT_EQ(m.shells[s.voidShells[0]].faces.size(), 1u);
  EXPECT_TRUE(m.shells[0].closed && m.shells[1].closed);
  expectSound(m);
  // Material normals: out of the box, and into the cavity (towards its centre).
  expectNormalsFrom(m, s.outerShell, Vec3(5, 5, 5), 1);
  expectNormalsFrom(m, s.voidShells[0], Vec3(5, 5, 5), -1);
}

TEST(BuildTopology, CompoundWithTwoSolidsAndALooseFace) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, BRepPrimAPI_MakeBox(1, 1, 1).Shape());
  b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(3, 0, 0), 1, 1, 1).Shape());
  b.Add(c, BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 5), gp_Dir(0, 0, 1)), 0, 2, 0, 1).Face());
  const Model m = build(c);
  ASSERT_EQ(m.solids.size(), 2u);
  EXPECT_EQ(m.solids[0].name, "S1");
  EXPECT_EQ(m.solids[1].name, "S2");
  EXPECT_NE(m.solids[0].outerShell, m.solids[1].outerShell);
  ASSERT_EQ(m.faces.size(), 13u);
  ASSERT_EQ(m.shells.size(), 2u);
  // The loose face (last in MapShapes order) is in no shell.
  for (const ModelShell& s : m.shells)
    for (const FaceUse& fu : s.faces) EXPECT_NE(fu.face, 12);
  const ModelFace& loose = m.faces[12];
  EXPECT_EQ(loose.loops.at(0).uses.size(), 4u);
  EXPECT_LT((m.bbox.hi - Vec3(4, 1, 5)).norm(), 1e-6);
  expectSound(m);
}

TEST(BuildTopology, AnUnboundedFaceWithoutBoundaryIsUnusableNotTheModel) {
  // A plane face with no wire (infinite): it has no usable surface, Model::check says so
  // (the pipeline leaves it out), the box is the other shapes' (threw for the whole model).
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, BRepPrimAPI_MakeBox(1, 2, 3).Shape());
  b.Add(c, BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 5), gp_Dir(0, 0, 1))).Face());
  const Model m = build(c);
  ASSERT_EQ(m.faces.size(), 7u);
  EXPECT_EQ(m.faces[6].surface, nullptr);
  for (int f = 0; f < 6; ++f) EXPECT_NE(m.faces[static_cast<std::size_t>(f)].surface, nullptr);
  EXPECT_LT((m.bbox.lo - Vec3(0, 0, 0)).norm(), 1e-6);
  EXPECT_LT((m.bbox.hi - Vec3(1, 2, 3)).norm(), 1e-6);
  bool reported = false;
  for (const ModelIssue& i : m.check())
    if (i.kind == EntityKind::Face && i.index == 6 && i.level == ModelIssue::Level::Unusable) reported = true;
  EXPECT_TRUE(reported);
}

TEST(BuildTopology, InternalFaceIsTakenForward) {
  const TopoDS_Face face =
      BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 0, 2, 0, 1).Face();
  const Model m = build(face.Oriented(TopAbs_INTERNAL));
  ASSERT_EQ(m.faces.size(), 1u);
  EXPECT_FALSE(m.faces[0].reversed);
  ASSERT_EQ(m.faces[0].loops.size(), 1u);
  EXPECT_EQ(m.faces[0].loops[0].uses.size(), 4u);
  expectSound(m);
}

TEST(BuildTopology, MovedAndReversedShapes) {
  gp_Trsf t;
  t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 1, 0)), 0.8);
  t.SetTranslationPart(gp_Vec(5, -2, 7));
  const TopoDS_Shape cyl = BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape();
  const Model moved = build(cyl.Moved(TopLoc_Location(t)));
  const Model plain = build(cyl);
  for (std::size_t v = 0; v < plain.vertices.size(); ++v) {
    const Vec3& p = plain.vertices[v].p;
    const gp_Pnt q = gp_Pnt(p.x(), p.y(), p.z()).Transformed(t);
    EXPECT_LT((moved.vertices[v].p - Vec3(q.X(), q.Y(), q.Z())).norm(), 1e-12);
  }
  expectSound(moved);

  // An inside-out solid: every face flips, the loops follow (still "face on the left").
  const Model inside = build(cyl.Reversed());
  for (std::size_t f = 0; f < plain.faces.size(); ++f)
    EXPECT_NE(inside.faces[f].reversed, plain.faces[f].reversed);
  expectSound(inside);
  expectNormalsFrom(inside, 0, Vec3(0, 0, 1), -1);
}

/// Counts of a public model from MANIFEST.json.
nlohmann::json manifestEntry(const std::string& file) {
  std::ifstream in(std::string(ANISOMESH_SHARED_DIR) + "/models/MANIFEST.json");
  const nlohmann::json all = nlohmann::json::parse(in);
  for (const nlohmann::json& e : all)
    if (e.at("file") == file) return e;
  return nlohmann::json();
}

TopoDS_Shape readBrep(const std::string& file) {
  TopoDS_Shape shape;
  BRep_Builder b;
  const std::string path = std::string(ANISOMESH_SHARED_DIR) + "/models/" + file;
  EXPECT_TRUE(BRepTools::Read(shape, path.c_str(), b)) << path;
  return shape;
}

class PublicBrep : public ::testing::TestWithParam<const char*> {};

TEST_P(PublicBrep, BuildsAndValidates) {
  const std::string file = GetParam();
  const TopoDS_Shape shape = readBrep(file);
  ASSERT_FALSE(shape.IsNull());
  const Model m = build(shape);
  const nlohmann::json want = manifestEntry(file);
  ASSERT_FALSE(want.is_null()) << file << " is not in MANIFEST.json";
  EXPECT_EQ(static_cast<int>(m.faces.size()), want.at("faces").get<int>());
  EXPECT_EQ(static_cast<int>(m.edges.size()), want.at("edges").get<int>());
  EXPECT_EQ(static_cast<int>(m.vertices.size()), want.at("vertices").get<int>());
  EXPECT_EQ(static_cast<int>(m.shells.size()), want.at("shells").get<int>());
  EXPECT_EQ(static_cast<int>(m.solids.size()), want.at("solids").get<int>());
  EXPECT_NEAR(m.diagonal(), want.at("diag").get<double>(), 1e-3 * want.at("diag").get<double>());
  Slack slack;
  slack.abs = 1e-7 * m.diagonal();
  slack.cadFactor = 2;
  slack.uvRel = 1e-4;
  expectSound(m, slack);
}

INSTANTIATE_TEST_SUITE_P(Models, PublicBrep,
                         ::testing::Values("cylinder.brep", "CylinderInnerLoopCrossingSeam.brep",
                                           "box.brep", "full_sphere.brep", "ring.brep",
                                           "SlenderSurface.brep", "TrimmedSurface.brep",
                                           "PeriodicFaceWithLargeTolerance.brep",
                                           "cube-sphere-cube-compound.brep"));

}  // namespace
}  // namespace aniso::cad
