// OcctSurface against analytic truth: derivatives, curvature, M_p, projection, domain,
// locations, clones and error conversion.
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_OffsetCurve.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopLoc_Location.hxx>
#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "cad/OcctSurface.h"
#include "mesher/core/Error.h"
#include "occt_test_util.h"

namespace aniso::cad {
namespace {

using test::faceOfType;
using test::kPi;

struct NamedFace {
  const char* name;
  TopoDS_Face face;
};

std::vector<NamedFace> sampleFaces() {
  return {
      {"sphere", faceOfType(BRepPrimAPI_MakeSphere(2.0).Shape(), GeomAbs_Sphere)},
      {"cylinder", faceOfType(BRepPrimAPI_MakeCylinder(1.5, 3.0).Shape(), GeomAbs_Cylinder)},
      {"torus", faceOfType(BRepPrimAPI_MakeTorus(3.0, 1.0).Shape(), GeomAbs_Torus)},
      {"cone", faceOfType(BRepPrimAPI_MakeCone(2.0, 1.0, 3.0).Shape(), GeomAbs_Cone)},
      {"plane", faceOfType(BRepPrimAPI_MakeBox(1.0, 2.0, 3.0).Shape(), GeomAbs_Plane)},
      {"bspline", test::bsplineFace()},
  };
}

/// (u,v) samples inside the face's parametric bounds, kept 10% away from their edges.
std::vector<Vec2> interiorSamples(const TopoDS_Face& face, int n = 5) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  std::vector<Vec2> s;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      s.emplace_back(u0 + (u1 - u0) * (0.1 + 0.8 * i / (n - 1)),
                     v0 + (v1 - v0) * (0.1 + 0.8 * j / (n - 1)));
  return s;
}

TEST(OcctSurface, DerivativesMatchFiniteDifferences) {
  for (const NamedFace& nf : sampleFaces()) {
    SCOPED_TRACE(nf.name);
    const OcctSurface s(nf.face, nf.name);
    for (const Vec2& uv : interiorSamples(nf.face)) {
      const SurfaceD2 d = s.d2(uv);
      const SurfaceD1 e = s.d1(uv);
      const double scale = 1.0 + d.pu.norm() + d.pv.norm();
      const double h = 1e-5;
      EXPECT_LT((d.p - s.point(uv)).norm(), 1e-14 * scale);
      EXPECT_LT((e.pu - d.pu).norm() + (e.pv - d.pv).norm(), 1e-13 * scale);
      const auto pu = [&](double u) { return s.point(Vec2(u, uv.y())); };
      const auto pv = [&](double v) { return s.point(Vec2(uv.x(), v)); };
      EXPECT_LT((test::centralDifference(pu, uv.x(), h) - d.pu).norm(), 1e-7 * scale);
      EXPECT_LT((test::centralDifference(pv, uv.y(), h) - d.pv).norm(), 1e-7 * scale);
      const auto du = [&](double u) { return s.d1(Vec2(u, uv.y())).pu; };
      const auto dv = [&](double v) { return s.d1(Vec2(uv.x(), v)).pv; };
      const auto duv = [&](double v) { return s.d1(Vec2(uv.x(), v)).pu; };
      EXPECT_LT((test::centralDifference(du, uv.x(), h) - d.puu).norm(), 1e-6 * scale);
      EXPECT_LT((test::centralDifference(dv, uv.y(), h) - d.pvv).norm(), 1e-6 * scale);
      EXPECT_LT((test::centralDifference(duv, uv.y(), h) - d.puv).norm(), 1e-6 * scale);
    }
  }
}

TEST(OcctSurface, DomainFromNaturalBoundsAndFace) {
  const OcctSurface sphere(faceOfType(BRepPrimAPI_MakeSphere(2.0).Shape(), GeomAbs_Sphere), "s");
  const SurfaceDomain d = sphere.domain();
  EXPECT_TRUE(d.uPeriodic);
  EXPECT_FALSE(d.vPeriodic);
  EXPECT_NEAR(d.uPeriod, 2 * kPi, 1e-14);
  EXPECT_NEAR(d.u0, 0, 1e-14);
  EXPECT_NEAR(d.u1, 2 * kPi, 1e-14);
  EXPECT_NEAR(d.v0, -kPi / 2, 1e-14);
  EXPECT_NEAR(d.v1, kPi / 2, 1e-14);

  // A cylinder is unbounded along v: the face's [0, 3] widened by 10% on each side.
  const OcctSurface cyl(faceOfType(BRepPrimAPI_MakeCylinder(1.5, 3.0).Shape(), GeomAbs_Cylinder),
                        "c");
  const SurfaceDomain c = cyl.domain();
  EXPECT_TRUE(c.uPeriodic);
  EXPECT_FALSE(c.vPeriodic);
  EXPECT_NEAR(c.v0, -0.3, 1e-9);
  EXPECT_NEAR(c.v1, 3.3, 1e-9);

  const TopoDS_Face torusFace = faceOfType(BRepPrimAPI_MakeTorus(3.0, 1.0).Shape(), GeomAbs_Torus);
  const SurfaceDomain t = OcctSurface(torusFace, "t").domain();
  EXPECT_TRUE(t.uPeriodic && t.vPeriodic);
  EXPECT_NEAR(t.vPeriod, 2 * kPi, 1e-14);
}

TEST(OcctSurface, LocationIsApplied) {
  const TopoDS_Shape sphere = BRepPrimAPI_MakeSphere(2.0).Shape();
  gp_Trsf move;
  move.SetTranslation(gp_Vec(10, -4, 1));
  const TopoDS_Shape moved = sphere.Moved(TopLoc_Location(move));
  const OcctSurface a(faceOfType(sphere, GeomAbs_Sphere), "a");
  const OcctSurface b(faceOfType(moved, GeomAbs_Sphere), "b");
  for (const Vec2& uv : {Vec2(0.3, 0.2), Vec2(4.0, -1.0)}) {
    EXPECT_LT((b.point(uv) - a.point(uv) - Vec3(10, -4, 1)).norm(), 1e-12);
    EXPECT_LT((b.d1(uv).pu - a.d1(uv).pu).norm(), 1e-12);
  }
}

TEST(OcctSurface, SphereCurvatureAndNormal) {
  const double r = 2.0;
  const OcctSurface s(faceOfType(BRepPrimAPI_MakeSphere(r).Shape(), GeomAbs_Sphere), "s");
  for (const Vec2& uv : {Vec2(0.2, 0.1), Vec2(3.0, -1.2), Vec2(5.5, 1.4)}) {
    const Vec3 p = s.point(uv);
    EXPECT_NEAR(s.normal(uv).dot(p / r), 1.0, 1e-12);  // pu × pv points outwards
    const PrincipalCurvatures k = s.curvature(uv);
    EXPECT_NEAR(k.k1, -1 / r, 1e-10);  // the surface bends away from the outward normal
    EXPECT_NEAR(k.k2, -1 / r, 1e-10);
    EXPECT_NEAR(k.maxAbs(), 1 / r, 1e-10);
  }
}

TEST(OcctSurface, CylinderCurvatureAndDirections) {
  const double r = 1.5;
  const OcctSurface s(
      faceOfType(BRepPrimAPI_MakeCylinder(r, 3.0).Shape(), GeomAbs_Cylinder), "c");
  for (const Vec2& uv : {Vec2(0.4, 1.0), Vec2(2.5, 2.0)}) {
    const PrincipalCurvatures k = s.curvature(uv);
    EXPECT_NEAR(k.k1, -1 / r, 1e-10);
    EXPECT_NEAR(k.k2, 0.0, 1e-10);
    EXPECT_NEAR(std::abs(k.dir1.x()), 1.0, 1e-8);  // curved along u (the circle)
    EXPECT_NEAR(std::abs(k.dir2.y()), 1.0, 1e-8);  // straight along v (the axis)
    const Vec3 tangent(-std::sin(uv.x()), std::cos(uv.x()), 0);
    EXPECT_NEAR(std::abs(k.d3_1.dot(tangent)), 1.0, 1e-8);
    EXPECT_NEAR(std::abs(k.d3_2.z()), 1.0, 1e-8);
  }
}

TEST(OcctSurface, TorusCurvatureOnBothEquators) {
  const double big = 3.0, small = 1.0;
  const OcctSurface s(
      faceOfType(BRepPrimAPI_MakeTorus(big, small).Shape(), GeomAbs_Torus), "t");
  // Outer equator (v = 0): both circles bend away from the outward normal.
  PrincipalCurvatures k = s.curvature(Vec2(0.7, 0.0));
  EXPECT_NEAR(k.k1, -1 / small, 1e-10);
  EXPECT_NEAR(k.k2, -1 / (big + small), 1e-10);
  // Inner equator (v = π): a saddle.
  k = s.curvature(Vec2(0.7, kPi));
  EXPECT_NEAR(k.k1, -1 / small, 1e-10);
  EXPECT_NEAR(k.k2, 1 / (big - small), 1e-10);
  // General v: the parallel's normal curvature is −cos v / (R + r cos v).
  const double v = 2.1;
  k = s.curvature(Vec2(0.7, v));
  const double kParallel = -std::cos(v) / (big + small * std::cos(v));
  EXPECT_NEAR(std::min(k.k1, k.k2), std::min(-1 / small, kParallel), 1e-10);
  EXPECT_NEAR(std::max(k.k1, k.k2), std::max(-1 / small, kParallel), 1e-10);
}

TEST(OcctSurface, SphereParameterizationTensorSquaresToG) {
  const double r = 2.0;
  const OcctSurface s(faceOfType(BRepPrimAPI_MakeSphere(r).Shape(), GeomAbs_Sphere), "s");
  for (const Vec2& uv : {Vec2(0.1, 0.0), Vec2(2.0, 0.9), Vec2(4.0, -1.3)}) {
    const Mat2 m = s.parameterizationTensor(uv, 1e-12);
    const Mat2 g = s.firstFundamentalForm(uv);
    EXPECT_NEAR(g(0, 0), r * r * std::cos(uv.y()) * std::cos(uv.y()), 1e-12);
    EXPECT_NEAR(g(1, 1), r * r, 1e-12);
    EXPECT_NEAR(g(0, 1), 0.0, 1e-12);
    EXPECT_LT((m - m.transpose()).norm(), 1e-14);
    EXPECT_LT((m * m - g).norm(), 1e-11);
  }
  // Near the pole g11 → 0: the guard keeps it at least gMin.
  const double gMin = 1e-4 * r * r;
  const Mat2 m = s.parameterizationTensor(Vec2(1.0, kPi / 2 - 1e-7), gMin);
  EXPECT_GE((m * m)(0, 0), gMin * (1 - 1e-9));
  EXPECT_NEAR((m * m)(1, 1), r * r, 1e-9);
}

TEST(OcctSurface, ProjectionNearTheSeamStaysNearTheStart) {
  const OcctSurface s(faceOfType(BRepPrimAPI_MakeSphere(2.0).Shape(), GeomAbs_Sphere), "s");
  const Vec3 x = s.point(Vec2(0.01, 0.3));
  Vec2 uv = s.project(x, Vec2(2 * kPi - 0.05, 0.25));
  EXPECT_NEAR(uv.x(), 2 * kPi + 0.01, 1e-10);
  EXPECT_NEAR(uv.y(), 0.3, 1e-10);
  uv = s.project(x, Vec2(0.05, 0.35));
  EXPECT_NEAR(uv.x(), 0.01, 1e-10);
  // Off the surface (outside and inside): the same parameters.
  for (const double scale : {1.2, 0.7}) {
    uv = s.project(scale * x, Vec2(2 * kPi - 0.1, 0.2));
    EXPECT_NEAR(uv.x(), 2 * kPi + 0.01, 1e-10);
    EXPECT_NEAR(uv.y(), 0.3, 1e-10);
  }
  // Torus: both parameters periodic.
  const OcctSurface t(faceOfType(BRepPrimAPI_MakeTorus(3.0, 1.0).Shape(), GeomAbs_Torus), "t");
  uv = t.project(t.point(Vec2(0.02, 6.25)), Vec2(6.25, 0.02));
  EXPECT_NEAR(uv.x(), 2 * kPi + 0.02, 1e-10);
  EXPECT_NEAR(uv.y(), 6.25 - 2 * kPi, 1e-10);
}

TEST(OcctSurface, ProjectionNearThePoles) {
  const double r = 2.0;
  const OcctSurface s(faceOfType(BRepPrimAPI_MakeSphere(r).Shape(), GeomAbs_Sphere), "s");
  for (const double v : {kPi / 2 - 1e-3, -kPi / 2 + 1e-5}) {
    const Vec3 x = s.point(Vec2(1.0, v));
    const Vec2 uv = s.project(x, Vec2(1.3, v > 0 ? 1.2 : -1.2));
    EXPECT_LT((s.point(uv) - x).norm(), 1e-9 * r);
    EXPECT_NEAR(uv.y(), v, 1e-6);
  }
  // The pole itself, from a start far from it.
  const Vec2 uv = s.project(Vec3(0, 0, r), Vec2(2.0, 0.1));
  EXPECT_LT((s.point(uv) - Vec3(0, 0, r)).norm(), 1e-9 * r);
}

TEST(OcctSurface, ProjectionFromTheFarthestPointFallsBackToTheGlobalSearch) {
  // Started at the farthest point (gradient zero, a maximum) the iteration cannot move;
  // the result must still be the nearest point.
  const double r = 2.0;
  const OcctSurface s(faceOfType(BRepPrimAPI_MakeSphere(r).Shape(), GeomAbs_Sphere), "s");
  Vec2 uv = s.project(Vec3(0, 0, 5), Vec2(1.0, -kPi / 2));  // from the opposite pole
  EXPECT_LT((s.point(uv) - Vec3(0, 0, r)).norm(), 1e-9);
  uv = s.project(Vec3(-3 * r, 0, 0), Vec2(0.0, 0.0));  // from the antipode
  EXPECT_LT((s.point(uv) - Vec3(-r, 0, 0)).norm(), 1e-9);
  EXPECT_NEAR(std::abs(uv.x()), kPi, 1e-9);  // unwrapped near the start: ±π, not 3π
}

TEST(OcctSurface, ProjectionRoundTripsOnAllSampleFaces) {
  for (const NamedFace& nf : sampleFaces()) {
    SCOPED_TRACE(nf.name);
    const OcctSurface s(nf.face, nf.name);
    for (const Vec2& uv : interiorSamples(nf.face, 4)) {
      const Vec3 x = s.point(uv) + 0.01 * s.normal(uv);
      const Vec2 start = uv + Vec2(0.05, -0.04);
      const Vec2 got = s.project(x, start);
      EXPECT_LT((got - uv).norm(), 1e-8) << "at (" << uv.x() << ", " << uv.y() << ")";
    }
  }
}

TEST(OcctSurface, ClonesEvaluateIndependentlyInThreads) {
  const OcctSurface s(test::bsplineFace(), "bspline");
  std::vector<Vec2> uv;
  for (int i = 0; i < 400; ++i) uv.emplace_back(4.0 * ((i * 37) % 400) / 400, 3.0 * i / 400);
  std::vector<Vec3> expected;
  for (const Vec2& p : uv) expected.push_back(s.d2(p).puv);
  std::vector<int> mismatches(2, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      const std::unique_ptr<ParametricSurface> c = s.clone();
      for (int rep = 0; rep < 20; ++rep)
        for (std::size_t i = 0; i < uv.size(); ++i) {
          const std::size_t k = t == 0 ? i : uv.size() - 1 - i;  // opposite orders
          if (c->d2(uv[k]).puv != expected[k]) ++mismatches[t];
        }
    });
  for (std::thread& th : threads) th.join();
  EXPECT_EQ(mismatches[0], 0);
  EXPECT_EQ(mismatches[1], 0);
  const std::unique_ptr<ParametricSurface> c = s.clone();
  EXPECT_EQ(c->domain().u1, s.domain().u1);
}

TEST(OcctSurface, OcctFailuresBecomeMeshingErrorsNamingTheFace) {
  // The offset of a curve collapsed to a point has no normal: OCCT throws
  // Standard_NullValue evaluating it, and so evaluating its extrusion.
  TColgp_Array1OfPnt poles(1, 2);
  poles(1) = poles(2) = gp_Pnt(1, 2, 3);
  Handle(Geom_OffsetCurve) offset =
      new Geom_OffsetCurve(new Geom_BezierCurve(poles), 0.5, gp_Dir(0, 0, 1));
  Handle(Geom_Surface) extrusion = new Geom_RectangularTrimmedSurface(
      new Geom_SurfaceOfLinearExtrusion(offset, gp_Dir(0, 0, 1)), 0.0, 1.0, 0.0, 1.0);
  TopoDS_Face face;
  BRep_Builder().MakeFace(face, extrusion, 1e-7);
  const OcctSurface s(face, "face 7");
  for (int what = 0; what < 3; ++what) {
    try {
      if (what == 0) s.point(Vec2(0.5, 0.2));
      if (what == 1) s.d1(Vec2(0.5, 0.2));
      if (what == 2) s.d2(Vec2(0.5, 0.2));
      ADD_FAILURE() << "no error from an undefined offset";
    } catch (const MeshingError& e) {
      EXPECT_NE(std::string(e.what()).find("face 7"), std::string::npos) << e.what();
    }
  }
  // project() never throws.
  EXPECT_NO_THROW(s.project(Vec3(1, 2, 3), Vec2(0.5, 0.2)));
}

}  // namespace
}  // namespace aniso::cad
