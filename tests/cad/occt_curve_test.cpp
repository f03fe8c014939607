// OcctCurve3d and OcctCurve2d against analytic truth: lengths (Euclidean and through the
// pcurve with M_p), curvature, projection, derivatives, seams, locations, errors.
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_OffsetCurve.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <gp_Ax3.hxx>
#include <gtest/gtest.h>

#include "cad/OcctCurve2d.h"
#include "cad/OcctCurve3d.h"
#include "cad/OcctSurface.h"
#include "mesher/core/Error.h"
#include "occt_test_util.h"

namespace aniso::cad {
namespace {

using test::faceOfType;
using test::kPi;

/// The first edge of `shape` whose curve is of `type`, not degenerate.
TopoDS_Edge edgeOfType(const TopoDS_Shape& shape, GeomAbs_CurveType type) {
  for (TopExp_Explorer x(shape, TopAbs_EDGE); x.More(); x.Next()) {
    const TopoDS_Edge& e = TopoDS::Edge(x.Current());
    if (BRep_Tool::Degenerated(e)) continue;
    double a, b;
    Handle(Geom_Curve) c = BRep_Tool::Curve(e, a, b);
    if (!c.IsNull() && GeomAdaptor_Curve(c).GetType() == type) return e;
  }
  throw std::runtime_error("no edge of the requested type");
}

/// The seam edge of a face (closed on it).
TopoDS_Edge seamOf(const TopoDS_Face& face) {
  for (TopExp_Explorer x(face, TopAbs_EDGE); x.More(); x.Next())
    if (BRep_Tool::IsClosed(TopoDS::Edge(x.Current()), face)) return TopoDS::Edge(x.Current());
  throw std::runtime_error("no seam");
}

TEST(OcctCurve3d, CircleLengthCurvatureProjection) {
  const double r = 1.5;
  const TopoDS_Shape cyl = BRepPrimAPI_MakeCylinder(r, 3.0).Shape();
  const OcctCurve3d c(edgeOfType(cyl, GeomAbs_Circle), "edge 1");
  EXPECT_NEAR(c.last() - c.first(), 2 * kPi, 1e-12);
  EXPECT_NEAR(c.length(c.first(), c.last()), 2 * kPi * r, 1e-9);
  EXPECT_NEAR(c.length(c.first(), c.first() + 1.0), r, 1e-10);
  for (const double t : {0.1, 2.0, 5.9}) {
    EXPECT_NEAR(c.curvature(t), 1 / r, 1e-10);
    EXPECT_NEAR(c.project(c.point(t), t + 0.2, c.first(), c.last()), t, 1e-9);
    const Curve3dD2 d = c.d2(t);
    const auto p = [&](double s) { return c.point(s); };
    const auto v = [&](double s) { return c.d2(s).d1; };
    EXPECT_LT((test::centralDifference(p, t, 1e-5) - d.d1).norm(), 1e-8);
    EXPECT_LT((test::centralDifference(v, t, 1e-5) - d.d2).norm(), 1e-8);
  }
  // A metric scaling lengths by 2 doubles the length.
  const double scaled =
      c.length(c.first(), c.last(), [](const Vec3&) { return Mat3(2 * Mat3::Identity()); });
  EXPECT_NEAR(scaled, 4 * kPi * r, 1e-8);
}

TEST(OcctCurve3d, BSplineDerivativesAndLocation) {
  TColgp_Array1OfPnt pts(1, 8);
  for (int i = 1; i <= 8; ++i)
    pts(i) = gp_Pnt(std::cos(0.6 * i), std::sin(0.6 * i), 0.3 * i);  // a helix-like spline
  const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(GeomAPI_PointsToBSpline(pts).Curve()).Edge();
  gp_Trsf rot;
  rot.SetRotation(gp_Ax1(gp_Pnt(1, 0, 0), gp_Dir(0, 1, 0)), 0.7);
  const TopoDS_Edge moved = TopoDS::Edge(edge.Moved(TopLoc_Location(rot)));
  const OcctCurve3d a(edge, "a"), b(moved, "b");
  for (double t = a.first(); t <= a.last(); t += 0.25 * (a.last() - a.first())) {
    const Curve3dD2 d = a.d2(t);
    const auto p = [&](double s) { return a.point(s); };
    const auto v = [&](double s) { return a.d2(s).d1; };
    const double h = 1e-6 * (a.last() - a.first());
    EXPECT_LT((test::centralDifference(p, t, h) - d.d1).norm(), 1e-6 * (1 + d.d1.norm()));
    EXPECT_LT((test::centralDifference(v, t, h) - d.d2).norm(), 1e-5 * (1 + d.d2.norm()));
    const gp_Pnt q = gp_Pnt(d.p.x(), d.p.y(), d.p.z()).Transformed(rot);
    EXPECT_LT((b.point(t) - Vec3(q.X(), q.Y(), q.Z())).norm(), 1e-12);
  }
  // The lengths agree (a rigid motion).
  EXPECT_NEAR(a.length(a.first(), a.last()), b.length(b.first(), b.last()), 1e-10);
  const std::unique_ptr<ParametricCurve3d> c = b.clone();
  EXPECT_EQ(c->point(0.3 * b.last()), b.point(0.3 * b.last()));
}

TEST(OcctCurve3d, EdgeWithoutA3dCurveUsesItsCurveOnSurface) {
  const double r = 2.0;
  Handle(Geom_CylindricalSurface) surf = new Geom_CylindricalSurface(gp_Ax3(), r);
  // A helix as a line in the cylinder's parameter plane: u = t, v = 0.5 t.
  Handle(Geom2d_Line) line = new Geom2d_Line(gp_Pnt2d(0, 0), gp_Dir2d(1, 0.5));
  const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(line, surf, 0.0, 4.0).Edge();
  double a = 0, b = 0;
  ASSERT_TRUE(BRep_Tool::Curve(edge, a, b).IsNull());
  const OcctCurve3d c(edge, "edge 9");
  EXPECT_TRUE(c.onSurface());
  const double dt = std::sqrt(1.25);  // |c'| in the plane for the unit-speed line
  for (const double t : {0.0, 1.0, 3.0}) {
    const double u = t / dt, v = 0.5 * t / dt;
    EXPECT_LT((c.point(t) - Vec3(r * std::cos(u), r * std::sin(u), v)).norm(), 1e-12);
  }
  // Helix: length = (parameter span) × sqrt(r² + 0.25) / sqrt(1.25).
  EXPECT_NEAR(c.length(0.0, 4.0), 4.0 * std::sqrt(r * r + 0.25) / dt, 1e-8);
}

TEST(OcctCurve3d, DegenerateEdgesAreRefused) {
  const TopoDS_Shape sphere = BRepPrimAPI_MakeSphere(1.0).Shape();
  for (TopExp_Explorer x(sphere, TopAbs_EDGE); x.More(); x.Next()) {
    const TopoDS_Edge& e = TopoDS::Edge(x.Current());
    if (BRep_Tool::Degenerated(e)) {
      EXPECT_THROW(OcctCurve3d(e, "edge 2"), MeshingError);
    }
  }
}

TEST(OcctCurve2d, CircleOnCylinderHasMetricLength2PiR) {
  const double r = 1.5;
  const TopoDS_Shape cyl = BRepPrimAPI_MakeCylinder(r, 3.0).Shape();
  const TopoDS_Face lateral = faceOfType(cyl, GeomAbs_Cylinder);
  const OcctSurface surface(lateral, "face 1");
  const TopoDS_Edge circle = edgeOfType(cyl, GeomAbs_Circle);
  const OcctCurve2d pc(circle, lateral, "edge 1 on face 1");
  const double t0 = pc.first(), t1 = pc.last();
  // In (u,v) the circle is a straight line of length 2π.
  EXPECT_NEAR(pc.length(t0, t1), 2 * kPi, 1e-10);
  const auto mp = [&](const Vec2& uv) { return surface.parameterizationTensor(uv, 1e-12); };
  EXPECT_NEAR(pc.length(t0, t1, mp), 2 * kPi * r, 1e-8);
  const OcctCurve3d c3(circle, "edge 1");
  EXPECT_NEAR(c3.length(c3.first(), c3.last()), pc.length(t0, t1, mp), 1e-8);
  for (const double t : {0.5, 3.0}) {
    EXPECT_NEAR(pc.curvature(t, surface), 1 / r, 1e-8);
    // Same parameter: the pcurve on the surface is the 3D curve.
    EXPECT_LT((surface.point(pc.point(t)) - c3.point(t)).norm(), 1e-7);
    EXPECT_NEAR(pc.project(pc.point(t), t - 0.3, t0, t1), t, 1e-9);
  }
}

TEST(OcctCurve2d, CircleOnPlaneHasMetricLength2PiR) {
  const double r = 1.5;
  const TopoDS_Shape cyl = BRepPrimAPI_MakeCylinder(r, 3.0).Shape();
  const TopoDS_Face cap = faceOfType(cyl, GeomAbs_Plane);
  const OcctSurface surface(cap, "face 2");
  TopoDS_Edge circle;
  for (TopExp_Explorer x(cap, TopAbs_EDGE); x.More(); x.Next()) circle = TopoDS::Edge(x.Current());
  const OcctCurve2d pc(circle, cap, "edge on cap");
  const auto mp = [&](const Vec2& uv) { return surface.parameterizationTensor(uv, 1e-12); };
  EXPECT_NEAR(pc.length(pc.first(), pc.last(), mp), 2 * kPi * r, 1e-8);
  EXPECT_NEAR(pc.curvature(1.0, surface), 1 / r, 1e-8);
  const auto p = [&](double s) { return pc.point(s); };
  EXPECT_LT((test::centralDifference(p, 1.0, 1e-5) - pc.d2(1.0).d1).norm(), 1e-8);
}

TEST(OcctCurve2d, SeamHasTwoPcurvesOnePeriodApart) {
  const double r = 2.0;
  const TopoDS_Face sphereFace =
      faceOfType(BRepPrimAPI_MakeSphere(r).Shape(), GeomAbs_Sphere);
  const TopoDS_Edge seam = seamOf(sphereFace);
  const TopoDS_Edge fwd = TopoDS::Edge(seam.Oriented(TopAbs_FORWARD));
  const TopoDS_Edge rev = TopoDS::Edge(seam.Oriented(TopAbs_REVERSED));
  const OcctCurve2d first(fwd, sphereFace, "first"), second(rev, sphereFace, "second");
  // The face's own orientation does not change which pcurve is chosen.
  const OcctCurve2d firstOnReversed(fwd, TopoDS::Face(sphereFace.Reversed()), "first'");
  const OcctSurface surface(sphereFace, "face 1");
  const OcctCurve3d c3(fwd, "seam");
  for (const double t : {-1.0, 0.0, 1.2}) {
    const Vec2 a = first.point(t), b = second.point(t);
    EXPECT_NEAR(std::abs(a.x() - b.x()), 2 * kPi, 1e-12);
    EXPECT_NEAR(a.y(), b.y(), 1e-12);
    EXPECT_EQ(firstOnReversed.point(t), a);
    EXPECT_LT((surface.point(a) - surface.point(b)).norm(), 1e-12);
    EXPECT_LT((surface.point(a) - c3.point(t)).norm(), 1e-9);
  }
  const auto mp = [&](const Vec2& uv) { return surface.parameterizationTensor(uv, 1e-12); };
  EXPECT_NEAR(first.length(first.first(), first.last(), mp), kPi * r, 1e-8);
  EXPECT_NEAR(c3.length(c3.first(), c3.last()), kPi * r, 1e-8);
}

TEST(OcctCurve3d, OcctFailuresBecomeMeshingErrorsNamingTheEdge) {
  // The offset of a curve collapsed to a point has no normal: OCCT throws evaluating it.
  TColgp_Array1OfPnt poles(1, 2);
  poles(1) = poles(2) = gp_Pnt(1, 2, 3);
  Handle(Geom_OffsetCurve) offset =
      new Geom_OffsetCurve(new Geom_BezierCurve(poles), 0.5, gp_Dir(0, 0, 1));
  TopoDS_Edge edge;
  BRep_Builder().MakeEdge(edge, offset, 1e-7);
  const OcctCurve3d c(edge, "edge 11");
  for (int what = 0; what < 2; ++what) {
    try {
      if (what == 0) c.point(0.5);
      if (what == 1) c.d2(0.5);
      ADD_FAILURE() << "no error from an undefined offset";
    } catch (const MeshingError& e) {
      EXPECT_NE(std::string(e.what()).find("edge 11"), std::string::npos) << e.what();
    }
  }
}

TEST(OcctCurve2d, MissingPcurveIsAMeshingErrorNamingThePair) {
  const TopoDS_Face lateral =
      faceOfType(BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape(), GeomAbs_Cylinder);
  const TopoDS_Edge boxEdge = edgeOfType(BRepPrimAPI_MakeBox(1, 1, 1).Shape(), GeomAbs_Line);
  try {
    OcctCurve2d(boxEdge, lateral, "edge 3 on face 5");
    ADD_FAILURE() << "no error for an edge that is not on the face";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("edge 3 on face 5"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace aniso::cad
