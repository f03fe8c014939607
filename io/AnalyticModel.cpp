#include "io/AnalyticModel.h"
#include "io/JsonFields.h"

#include <muParser.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"
#include "mesher/geometry/Circle2d.h"
#include "mesher/geometry/CurveOnSurface3d.h"
#include "mesher/geometry/ExpressionSurface.h"
#include "mesher/geometry/Line2d.h"
#include "mesher/geometry/PlaneSurface.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::io {
namespace {

using nlohmann::json;

using Reader = JsonFields;

/// Loop builder: adds vertices, edges (line or circle pcurves) and uses to the model.
struct LoopBuilder {
  Model& model;
  SurfacePtr surface;

  int vertex(const Vec2& uv) {
    model.vertices.push_back({surface->point(uv), 0.0});
    return static_cast<int>(model.vertices.size()) - 1;
  }
  void edge(Loop& loop, Curve2dPtr pcurve, int v0, int v1, bool reversed) {
    ModelEdge e;
    e.v0 = v0;
    e.v1 = v1;
    e.t0 = pcurve->tMin();
    e.t1 = pcurve->tMax();
    e.curve = std::make_shared<CurveOnSurface3d>(surface, pcurve);
    e.pcurves.push_back({0, pcurve, e.t0, e.t1, false});
    e.faces.push_back(0);
    model.edges.push_back(std::move(e));
    loop.uses.push_back({static_cast<int>(model.edges.size()) - 1, reversed, 0});
  }
  /// A closed polygon loop through `pts` in the given order.
  Loop polygon(const std::vector<Vec2>& pts, bool outer) {
    Loop loop;
    loop.outer = outer;
    std::vector<int> vs;
    for (const Vec2& p : pts) vs.push_back(vertex(p));
    for (size_t i = 0; i < pts.size(); ++i) {
      const size_t j = (i + 1) % pts.size();
      edge(loop, std::make_shared<Line2d>(pts[i], pts[j]), vs[i], vs[j], false);
    }
    return loop;
  }
};

double signedArea(const std::vector<Vec2>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2& q = p[i];
    const Vec2& r = p[(i + 1) % p.size()];
    a += q.x() * r.y() - r.x() * q.y();
  }
  return 0.5 * a;
}

bool segmentsCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  using predicates::orient2d;
  const double o1 = orient2d(a.data(), b.data(), c.data()), o2 = orient2d(a.data(), b.data(), d.data());
  const double o3 = orient2d(c.data(), d.data(), a.data()), o4 = orient2d(c.data(), d.data(), b.data());
  return ((o1 > 0) != (o2 > 0) || o1 == 0 || o2 == 0) && ((o3 > 0) != (o4 > 0) || o3 == 0 || o4 == 0) &&
         !(o1 == 0 && o2 == 0);  // collinear pairs are caught by the vertex checks
}

/// A hole as a polygon approximation for the containment and overlap checks.
struct HoleShape {
  std::vector<Vec2> outline;  // counter-clockwise
  Box2 box;
};

bool insidePolygon(const Vec2& p, const std::vector<Vec2>& poly) {
  bool in = false;
  for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    if ((poly[i].y() > p.y()) != (poly[j].y() > p.y()) &&
        p.x() < (poly[j].x() - poly[i].x()) * (p.y() - poly[i].y()) / (poly[j].y() - poly[i].y()) + poly[i].x())
      in = !in;
  }
  return in;
}

bool shapesOverlap(const HoleShape& a, const HoleShape& b) {
  if (a.box.hi.x() < b.box.lo.x() || b.box.hi.x() < a.box.lo.x() || a.box.hi.y() < b.box.lo.y() ||
      b.box.hi.y() < a.box.lo.y())
    return false;
  for (size_t i = 0; i < a.outline.size(); ++i)
    for (size_t j = 0; j < b.outline.size(); ++j)
      if (segmentsCross(a.outline[i], a.outline[(i + 1) % a.outline.size()], b.outline[j],
                        b.outline[(j + 1) % b.outline.size()]))
        return true;
  return insidePolygon(a.outline[0], b.outline) || insidePolygon(b.outline[0], a.outline);
}

/// The sizing expressions must parse and give a finite angle and positive lengths at the
/// domain centre (the control space checks every point it evaluates later).
void checkSizingExpressions(const Reader& r, const AnalyticSizing& s, const Vec2& centre) {
  double u = centre.x(), v = centre.y();
  const std::pair<const char*, const std::string*> exprs[] = {{"angle", &s.angle}, {"h1", &s.h1}, {"h2", &s.h2}};
  for (const auto& [name, text] : exprs) {
    double val = 0;
    try {
      mu::Parser p;
      p.DefineVar("u", &u);
      p.DefineVar("v", &v);
      p.DefineConst("pi", M_PI);
      p.SetExpr(*text);
      val = p.Eval();
    } catch (const mu::Parser::exception_type& e) {
      r.fail(std::string("sizing.") + name + " \"" + *text + "\": " + e.GetMsg());
    }
    if (!std::isfinite(val) || (name[0] == 'h' && val <= 0))
      r.fail(std::string("sizing.") + name + " \"" + *text + "\" must give a finite" +
             (name[0] == 'h' ? " positive" : "") + " value (got " + std::to_string(val) + " at the domain centre)");
  }
}

}  // namespace

bool isAnalyticModelPath(const std::string& path) {
  return lowerExtension(path) == ".json";
}

AnalyticModel readAnalyticModel(const std::string& path) {
  const Reader r(path);
  const json j = r.parseObject("analytic model");

  AnalyticModel out;
  out.name = j.value("name", std::filesystem::path(path).stem().string());
  const json& dom = r.field(j, "domain", "the model");
  const Vec2 ur = r.vec2(r.field(dom, "u", "domain"), "domain.u");
  const Vec2 vr = r.vec2(r.field(dom, "v", "domain"), "domain.v");
  if (!(ur[0] < ur[1]) || !(vr[0] < vr[1])) r.fail("domain must have u0 < u1 and v0 < v1");

  const json& sj = r.field(j, "surface", "the model");
  const std::string type = sj.value("type", "");
  SurfacePtr surface;
  try {
    if (type == "plane") {
      const Vec3 o = sj.contains("origin") ? r.vec3(sj["origin"], "surface.origin") : Vec3::Zero();
      const Vec3 a = sj.contains("u_axis") ? r.vec3(sj["u_axis"], "surface.u_axis") : Vec3::UnitX();
      const Vec3 b = sj.contains("v_axis") ? r.vec3(sj["v_axis"], "surface.v_axis") : Vec3::UnitY();
      surface = std::make_shared<PlaneSurface>(o, a, b, ur[0], ur[1], vr[0], vr[1]);
    } else if (type == "expression") {
      SurfaceDomain d;
      d.u0 = ur[0], d.u1 = ur[1], d.v0 = vr[0], d.v1 = vr[1];
      surface = std::make_shared<ExpressionSurface>(r.expression(r.field(sj, "x", "surface"), "surface.x"),
                                                    r.expression(r.field(sj, "y", "surface"), "surface.y"),
                                                    r.expression(r.field(sj, "z", "surface"), "surface.z"), d);
    } else {
      r.fail("surface.type must be \"plane\" or \"expression\"");
    }
  } catch (const InputError& e) {
    if (std::string(e.what()).rfind(path, 0) == 0) throw;
    r.fail(e.what());
  }

  Model& m = out.model;
  ModelFace face;
  face.surface = surface;
  LoopBuilder lb{m, surface};
  const std::vector<Vec2> rect = {{ur[0], vr[0]}, {ur[1], vr[0]}, {ur[1], vr[1]}, {ur[0], vr[1]}};
  face.loops.push_back(lb.polygon(rect, true));

  std::vector<HoleShape> shapes;
  if (j.contains("holes")) {
    if (!j["holes"].is_array()) r.fail("holes must be an array");
    int k = 0;
    for (const json& h : j["holes"]) {
      const std::string where = "holes[" + std::to_string(k++) + "]";
      const std::string ht = h.value("type", "");
      HoleShape shape;
      if (ht == "circle") {
        const Vec2 c = r.vec2(r.field(h, "center", where), where + ".center");
        const double rad = r.number(r.field(h, "radius", where), where + ".radius");
        if (rad <= 0) r.fail(where + ".radius must be positive");
        for (int i = 0; i < 64; ++i) {
          const double t = 2 * M_PI * i / 64;
          shape.outline.push_back(c + rad / std::cos(M_PI / 64) * Vec2(std::cos(t), std::sin(t)));
        }
        Loop loop;
        const int v = lb.vertex(c + Vec2(rad, 0));
        // The circle pcurve runs counter-clockwise; a hole is walked clockwise.
        lb.edge(loop, std::make_shared<Circle2d>(c, rad), v, v, true);
        face.loops.push_back(std::move(loop));
      } else if (ht == "polygon") {
        const json& pts = r.field(h, "points", where);
        if (!pts.is_array() || pts.size() < 3) r.fail(where + ".points must list at least 3 points");
        for (const json& p : pts) shape.outline.push_back(r.vec2(p, where + ".points"));
        const double a = signedArea(shape.outline);
        if (a == 0) r.fail(where + " has zero area");
        if (a < 0) std::reverse(shape.outline.begin(), shape.outline.end());
        for (size_t i = 0; i < shape.outline.size(); ++i)
          for (size_t q = i + 1; q < shape.outline.size(); ++q) {
            if (q == i + 1 || (i == 0 && q + 1 == shape.outline.size())) continue;
            if (segmentsCross(shape.outline[i], shape.outline[i + 1], shape.outline[q],
                              shape.outline[(q + 1) % shape.outline.size()]))
              r.fail(where + " crosses itself");
          }
        std::vector<Vec2> cw(shape.outline.rbegin(), shape.outline.rend());
        face.loops.push_back(lb.polygon(cw, false));
      } else {
        r.fail(where + ".type must be \"circle\" or \"polygon\"");
      }
      for (const Vec2& p : shape.outline) {
        shape.box.add(p);
        if (!(p.x() > ur[0] && p.x() < ur[1] && p.y() > vr[0] && p.y() < vr[1]))
          r.fail(where + " is not strictly inside the domain");
      }
      for (const HoleShape& other : shapes)
        if (shapesOverlap(shape, other)) r.fail(where + " overlaps another hole");
      shapes.push_back(std::move(shape));
    }
  }
  face.uvBounds.add(rect[0]);
  face.uvBounds.add(rect[2]);
  m.faces.push_back(std::move(face));
  // Bounding box: the boundary and a sample of the interior (a curved patch may bulge).
  for (const ModelEdge& e : m.edges)
    for (double t : e.curve->polyline(e.t0, e.t1)) m.bbox.add(e.curve->point(t));
  for (int a = 0; a <= 16; ++a)
    for (int b = 0; b <= 16; ++b)
      m.bbox.add(surface->point({ur[0] + (ur[1] - ur[0]) * a / 16, vr[0] + (vr[1] - vr[0]) * b / 16}));

  if (j.contains("sizing")) {
    const json& sz = j["sizing"];
    AnalyticSizing s;
    if (sz.contains("angle")) s.angle = r.expression(sz["angle"], "sizing.angle");
    s.h1 = r.expression(r.field(sz, "h1", "sizing"), "sizing.h1");
    s.h2 = sz.contains("h2") ? r.expression(sz["h2"], "sizing.h2") : s.h1;
    checkSizingExpressions(r, s, Vec2(0.5 * (ur[0] + ur[1]), 0.5 * (vr[0] + vr[1])));
    out.sizing = s;
  }
  const std::vector<std::string> problems = m.validate();
  if (!problems.empty()) r.fail("invalid model: " + problems.front());
  return out;
}

}  // namespace aniso::io
