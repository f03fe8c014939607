#pragma once
// Small analytic models for the contour discretization tests: planar polygons sharing
// edges, a disc, a lens (two edges between the same vertices), the lateral face of a
// cylinder (seam) and a sphere (seam and poles), built as OCCT would build them (see
// mesher/model/Model.h for the conventions).
#include <algorithm>
#include <memory>
#include <numbers>
#include <vector>

#include "mesher/control/CSAnalytic2d.h"
#include "mesher/geometry/Circle2d.h"
#include "mesher/geometry/Circle3d.h"
#include "mesher/geometry/CylinderSurface.h"
#include "mesher/geometry/Line2d.h"
#include "mesher/geometry/Line3d.h"
#include "mesher/geometry/PlaneSurface.h"
#include "mesher/geometry/SphereSurface.h"
#include "mesher/model/Model.h"

namespace aniso::test {

inline constexpr double kPi = std::numbers::pi;

class ModelBuilder {
 public:
  Model m;

  int vertex(const Vec3& p) {
    m.vertices.push_back({p, 1e-7});
    m.bbox.add(p);
    return static_cast<int>(m.vertices.size()) - 1;
  }
  int face(SurfacePtr s, const Box2& uv, bool reversed = false) {
    ModelFace f;
    f.surface = std::move(s);
    f.uvBounds = uv;
    f.reversed = reversed;
    m.faces.push_back(std::move(f));
    return static_cast<int>(m.faces.size()) - 1;
  }
  int edge(int v0, int v1, Curve3dPtr c, double t0, double t1) {
    ModelEdge e;
    e.v0 = v0;
    e.v1 = v1;
    e.curve = std::move(c);
    e.t0 = t0;
    e.t1 = t1;
    e.tolerance = 1e-7;
    m.edges.push_back(std::move(e));
    return static_cast<int>(m.edges.size()) - 1;
  }
  /// A straight edge between two vertices, t ∈ [0, 1].
  int line(int v0, int v1) {
    return edge(v0, v1, std::make_shared<Line3d>(m.vertices[v0].p, m.vertices[v1].p), 0, 1);
  }
  int degenerate(int v, double t0, double t1) {
    ModelEdge e;
    e.v0 = e.v1 = v;
    e.degenerate = true;
    e.t0 = t0;
    e.t1 = t1;
    m.edges.push_back(std::move(e));
    return static_cast<int>(m.edges.size()) - 1;
  }
  /// Adds a pcurve of edge e on face f (the edge's parameter range); returns its index.
  int pcurve(int e, int f, Curve2dPtr c, bool seamSecond = false) {
    ModelEdge& ed = m.edges[e];
    ed.pcurves.push_back({f, std::move(c), ed.t0, ed.t1, seamSecond});
    bool listed = false;
    for (int g : ed.faces) listed = listed || g == f;
    if (!listed) ed.faces.push_back(f);
    if (seamSecond) ed.seam = true;
    return static_cast<int>(ed.pcurves.size()) - 1;
  }
  void loop(int f, std::vector<EdgeUse> uses, bool outer) {
    m.faces[f].loops.push_back({std::move(uses), outer});
  }
};

inline SurfacePtr xyPlane(double u0 = -10, double u1 = 10, double v0 = -10, double v1 = 10) {
  return std::make_shared<PlaneSurface>(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), u0, u1, v0, v1);
}

inline Box2 box(double u0, double v0, double u1, double v1) {
  Box2 b;
  b.add(Vec2(u0, v0));
  b.add(Vec2(u1, v1));
  return b;
}

/// Polygon loop on face f of the plane z = 0 (uv = xy) through the given vertices, with new
/// straight edges; `vs` in walking order. Returns the edge indices.
inline std::vector<int> polygonLoop(ModelBuilder& b, int f, const std::vector<int>& vs, bool outer) {
  std::vector<int> edges;
  std::vector<EdgeUse> uses;
  for (std::size_t i = 0; i < vs.size(); ++i) {
    const int a = vs[i], c = vs[(i + 1) % vs.size()];
    const int e = b.line(a, c);
    const Vec3 pa = b.m.vertices[a].p, pc = b.m.vertices[c].p;
    const int k = b.pcurve(e, f, std::make_shared<Line2d>(Vec2(pa.x(), pa.y()), Vec2(pc.x(), pc.y())));
    edges.push_back(e);
    uses.push_back({e, false, k});
  }
  b.loop(f, uses, outer);
  return edges;
}

/// The unit square [0,1]² of the plane z = 0: vertices (0,0), (1,0), (1,1), (0,1), edges
/// 0..3 counter-clockwise.
inline Model unitSquare(bool reversed = false) {
  ModelBuilder b;
  const int f = b.face(xyPlane(), box(0, 0, 1, 1), reversed);
  std::vector<int> vs = {b.vertex({0, 0, 0}), b.vertex({1, 0, 0}), b.vertex({1, 1, 0}), b.vertex({0, 1, 0})};
  if (!reversed) {
    polygonLoop(b, f, vs, true);
  } else {
    // The region is on the right of the loops of a reversed face: walk clockwise.
    std::reverse(vs.begin(), vs.end());
    polygonLoop(b, f, vs, true);
  }
  return b.m;
}

/// Two unit squares side by side, [0,1]×[0,1] (face 0) and [1,2]×[0,1] (face 1), sharing
/// the edge x = 1 (edge 1, from (1,0) to (1,1): forward in face 0, reversed in face 1).
inline Model twoSquares() {
  ModelBuilder b;
  const int f0 = b.face(xyPlane(), box(0, 0, 1, 1)), f1 = b.face(xyPlane(), box(1, 0, 2, 1));
  const int v00 = b.vertex({0, 0, 0}), v10 = b.vertex({1, 0, 0}), v11 = b.vertex({1, 1, 0}), v01 = b.vertex({0, 1, 0});
  const int v20 = b.vertex({2, 0, 0}), v21 = b.vertex({2, 1, 0});
  const auto lineOn = [&](int e, int f) {
    const Vec3 p = b.m.vertices[b.m.edges[e].v0].p, q = b.m.vertices[b.m.edges[e].v1].p;
    return b.pcurve(e, f, std::make_shared<Line2d>(Vec2(p.x(), p.y()), Vec2(q.x(), q.y())));
  };
  const int e0 = b.line(v00, v10), e1 = b.line(v10, v11), e2 = b.line(v11, v01), e3 = b.line(v01, v00);
  const int e4 = b.line(v10, v20), e5 = b.line(v20, v21), e6 = b.line(v21, v11);
  for (int e : {e0, e1, e2, e3}) lineOn(e, f0);
  const int shared = lineOn(e1, f1);
  for (int e : {e4, e5, e6}) lineOn(e, f1);
  b.loop(f0, {{e0, false, 0}, {e1, false, 0}, {e2, false, 0}, {e3, false, 0}}, true);
  b.loop(f1, {{e4, false, 0}, {e5, false, 0}, {e6, false, 0}, {e1, true, shared}}, true);
  return b.m;
}

/// The unit disc of the plane z = 0, bounded by one closed circle edge (t ∈ [0, 2π]).
inline Model disc(double r = 1) {
  ModelBuilder b;
  const int f = b.face(xyPlane(), box(-r, -r, r, r));
  const int v = b.vertex({r, 0, 0});
  const int e = b.edge(v, v, std::make_shared<Circle3d>(Frame(), r), 0, 2 * kPi);
  const int k = b.pcurve(e, f, std::make_shared<Circle2d>(Vec2(0, 0), r));
  b.loop(f, {{e, false, k}}, true);
  return b.m;
}

/// The upper half of the unit disc: a half-circle arc (edge 0) and the diameter (edge 1),
/// both between the vertices (1,0,0) and (−1,0,0).
inline Model lens() {
  ModelBuilder b;
  const int f = b.face(xyPlane(), box(-1, 0, 1, 1));
  const int a = b.vertex({1, 0, 0}), c = b.vertex({-1, 0, 0});
  const int arc = b.edge(a, c, std::make_shared<Circle3d>(Frame(), 1), 0, kPi);
  b.pcurve(arc, f, std::make_shared<Circle2d>(Vec2(0, 0), 1));
  const int dia = b.line(c, a);
  b.pcurve(dia, f, std::make_shared<Line2d>(Vec2(-1, 0), Vec2(1, 0)));
  b.loop(f, {{arc, false, 0}, {dia, false, 0}}, true);
  return b.m;
}

/// The lateral face of the cylinder of radius r, height h around z: bottom circle (edge 0),
/// top circle (edge 1), seam (edge 2, pcurve 0 at u = 2π, pcurve 1 at u = 0).
/// `topShift` moves the top circle's pcurve by that much in u (OCCT may store a pcurve one
/// period away).
inline Model cylinder(double r = 1, double h = 2, double topShift = 0) {
  ModelBuilder b;
  auto cyl = std::make_shared<CylinderSurface>(Frame(), r, 0, h);
  const int f = b.face(cyl, box(0, 0, 2 * kPi, h));
  const int v0 = b.vertex({r, 0, 0}), v1 = b.vertex({r, 0, h});
  const int bottom = b.edge(v0, v0, std::make_shared<Circle3d>(Frame(), r), 0, 2 * kPi);
  const int top = b.edge(v1, v1, std::make_shared<Circle3d>(Frame(Vec3(0, 0, h), Vec3::UnitZ()), r), 0, 2 * kPi);
  const int seam = b.edge(v0, v1, std::make_shared<Line3d>(Vec3(r, 0, 0), Vec3(r, 0, h), 0, h), 0, h);
  b.pcurve(bottom, f, std::make_shared<Line2d>(Vec2(0, 0), Vec2(2 * kPi, 0), 0, 2 * kPi));
  b.pcurve(top, f, std::make_shared<Line2d>(Vec2(topShift, h), Vec2(topShift + 2 * kPi, h), 0, 2 * kPi));
  b.pcurve(seam, f, std::make_shared<Line2d>(Vec2(2 * kPi, 0), Vec2(2 * kPi, h), 0, h));
  b.pcurve(seam, f, std::make_shared<Line2d>(Vec2(0, 0), Vec2(0, h), 0, h), true);
  b.loop(f, {{bottom, false, 0}, {seam, false, 0}, {top, true, 0}, {seam, true, 1}}, true);
  b.m.bbox.add(Vec3(-r, -r, 0));
  b.m.bbox.add(Vec3(r, r, h));
  return b.m;
}

/// The closed cylinder: the lateral face of cylinder() and two planar caps (the bottom one
/// reversed, its normal −z pointing out of the solid).
inline Model cappedCylinder(double r, double h) {
  ModelBuilder b;
  b.m = cylinder(r, h);
  const int bottom = b.face(std::make_shared<PlaneSurface>(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), -r, r, -r, r),
                            box(-r, -r, r, r), true);
  const int top = b.face(std::make_shared<PlaneSurface>(Vec3(0, 0, h), Vec3::UnitX(), Vec3::UnitY(), -r, r, -r, r),
                         box(-r, -r, r, r), false);
  const int kb = b.pcurve(0, bottom, std::make_shared<Circle2d>(Vec2(0, 0), r));
  const int kt = b.pcurve(1, top, std::make_shared<Circle2d>(Vec2(0, 0), r));
  b.loop(bottom, {{0, true, kb}}, true);  // a reversed face has its region on the right
  b.loop(top, {{1, false, kt}}, true);
  b.m.shells.push_back({{{0, false}, {bottom, false}, {top, false}}, true});
  return b.m;
}

/// The full sphere of radius r: seam (edge 0, pcurve 0 at u = 2π, pcurve 1 at u = 0), south
/// pole (edge 1) and north pole (edge 2) degenerate, vertices 0 (south) and 1 (north).
inline Model sphere(double r = 1) {
  ModelBuilder b;
  auto s = std::make_shared<SphereSurface>(Frame(), r);
  const int f = b.face(s, box(0, -kPi / 2, 2 * kPi, kPi / 2));
  const int south = b.vertex({0, 0, -r}), north = b.vertex({0, 0, r});
  const Vec2 sw(0, -kPi / 2), se(2 * kPi, -kPi / 2), nw(0, kPi / 2), ne(2 * kPi, kPi / 2);
  const int seam = b.edge(south, north, std::make_shared<Circle3d>(Frame(Vec3::Zero(), -Vec3::UnitY(), Vec3::UnitX()), r),
                          -kPi / 2, kPi / 2);
  b.pcurve(seam, f, std::make_shared<Line2d>(se, ne, -kPi / 2, kPi / 2));
  b.pcurve(seam, f, std::make_shared<Line2d>(sw, nw, -kPi / 2, kPi / 2), true);
  const int ps = b.degenerate(south, 0, 2 * kPi), pn = b.degenerate(north, 0, 2 * kPi);
  b.pcurve(ps, f, std::make_shared<Line2d>(sw, se, 0, 2 * kPi));
  b.pcurve(pn, f, std::make_shared<Line2d>(nw, ne, 0, 2 * kPi));
  b.loop(f, {{ps, false, 0}, {seam, false, 0}, {pn, true, 0}, {seam, true, 1}}, true);
  b.m.bbox.add(Vec3(-r, -r, -r));
  b.m.bbox.add(Vec3(r, r, r));
  return b.m;
}

/// A control space with sizing f on face f of the model (M_p from the face's surface).
inline std::unique_ptr<CSAnalytic2d> space(const Model& m, int f, CSAnalytic2d::MetricFunction sizing,
                                           double gMin = 0) {
  Box2 b = m.faces[f].uvBounds;
  return std::make_unique<CSAnalytic2d>(b, std::move(sizing), m.faces[f].surface, gMin);
}

inline CSAnalytic2d::MetricFunction isotropic(double h) {
  return [h](const Vec2&) { return Metric2d::isotropic(h); };
}

/// Signed area of a closed polygon in (u, v) (positive counter-clockwise).
template <class Loop>
double signedArea(const Loop& loop) {
  double a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2& p = loop[i].uv;
    const Vec2& q = loop[(i + 1) % loop.size()].uv;
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

}  // namespace aniso::test
