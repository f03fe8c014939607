// Model::validate — structural checks of the boundary representation (thesis sec. 6.2:
// "the validity of the domain has to be verified before the meshing process").
//
// Geometric coincidences (curve ends at vertices, loop closure) are tested in 3D within
// 2 × the largest CAD tolerance involved plus kRelativeSlack × the model size. Loop
// closure is also required in the parametric plane: consecutive uses must meet within
// kUvGapRatio of the face's parametric extent (a gap across a pole or a seam is 0 in 3D
// but not in (u,v)), and the straight (u,v) segment bridging a gap must stay within the
// 3D tolerance (tested at its ends and midpoint).
#include "mesher/model/Model.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace aniso {

namespace {

constexpr double kRelativeSlack = 1e-6;
constexpr double kUvGapRatio = 1e-2;

std::string fmt(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

class Validator {
 public:
  explicit Validator(const Model& m) : m_(m) {
    scale_ = m.diagonal();
    if (!(scale_ > 0)) {
      Box3 b;
      for (const ModelVertex& v : m.vertices) b.add(v.p);
      scale_ = b.diagonal();
    }
    if (!(scale_ > 0) || !std::isfinite(scale_)) scale_ = 1;
  }

  std::vector<ModelIssue> run() {
    for (size_t i = 0; i < m_.edges.size(); ++i) at(EntityKind::Edge, i), checkEdge(static_cast<int>(i));
    for (size_t i = 0; i < m_.faces.size(); ++i) at(EntityKind::Face, i), checkFace(static_cast<int>(i));
    for (size_t i = 0; i < m_.shells.size(); ++i) at(EntityKind::Shell, i), checkShell(static_cast<int>(i));
    for (size_t i = 0; i < m_.solids.size(); ++i) at(EntityKind::Solid, i), checkSolid(static_cast<int>(i));
    return std::move(out_);
  }

 private:
  const Model& m_;
  double scale_ = 1;
  std::vector<ModelIssue> out_;
  EntityKind kind_ = EntityKind::Model;
  int index_ = -1;

  void at(EntityKind k, size_t i) {
    kind_ = k;
    index_ = static_cast<int>(i);
  }

  template <class V>
  static bool inRange(int i, const V& v) { return i >= 0 && static_cast<size_t>(i) < v.size(); }

  /// A problem of the entity being checked: Unusable unless said otherwise.
  void problem(const std::string& s, ModelIssue::Level level = ModelIssue::Level::Unusable) {
    out_.push_back({kind_, index_, level, s});
  }
  void defect(const std::string& s, ModelIssue::Level level = ModelIssue::Level::Defect) { problem(s, level); }

  double tolerance(std::initializer_list<double> tols) const {
    double t = 0;
    for (double x : tols) if (std::isfinite(x)) t = std::max(t, x);
    return 2 * t + kRelativeSlack * scale_;
  }

  double vertexTol(int v) const { return inRange(v, m_.vertices) ? m_.vertices[v].tolerance : 0; }

  void checkEdge(int e) {
    const ModelEdge& ed = m_.edges[e];
    const std::string name = "edge " + std::to_string(e + 1);
    const bool verticesOk = inRange(ed.v0, m_.vertices) && inRange(ed.v1, m_.vertices);
    if (!verticesOk) problem(name + ": vertex reference out of range");
    if (!std::isfinite(ed.t0) || !std::isfinite(ed.t1)) problem(name + ": non-finite parameter range");
    if (ed.degenerate && ed.v0 != ed.v1) problem(name + ": degenerate edge with two different vertices");
    if (!ed.degenerate && !ed.curve) problem(name + ": no 3D curve");
    if (verticesOk && ed.curve && !ed.degenerate) checkEnds(name + " 3D curve", ed, ed.curve->point(ed.t0), ed.curve->point(ed.t1), ed.tolerance);

    std::map<int, int> perFace;
    for (size_t k = 0; k < ed.pcurves.size(); ++k) {
      const PCurve& pc = ed.pcurves[k];
      const std::string pname = name + " pcurve " + std::to_string(k + 1);
      if (!inRange(pc.face, m_.faces)) { problem(pname + ": face reference out of range"); continue; }
      ++perFace[pc.face];
      if (!pc.curve) { problem(pname + ": no curve"); continue; }
      if (std::find(ed.faces.begin(), ed.faces.end(), pc.face) == ed.faces.end())
        defect(pname + ": face " + std::to_string(pc.face + 1) + " is not listed among the edge's faces");
      const ModelFace& f = m_.faces[pc.face];
      if (verticesOk && f.surface)
        checkEnds(pname + " on face " + std::to_string(pc.face + 1), ed,
                  f.surface->point(pc.curve->point(pc.t0)), f.surface->point(pc.curve->point(pc.t1)),
                  std::max(ed.tolerance, f.tolerance));
    }
    for (int f : ed.faces) {
      if (!inRange(f, m_.faces)) { problem(name + ": face reference out of range"); continue; }
      if (!perFace.count(f)) problem(name + ": no pcurve on face " + std::to_string(f + 1));
    }
    for (const auto& [f, n] : perFace) {
      if (n > 2) problem(name + ": " + std::to_string(n) + " pcurves on face " + std::to_string(f + 1));
      if (n == 2 && !ed.seam) problem(name + ": two pcurves on face " + std::to_string(f + 1) + " but not marked seam");
      if (n == 2) {
        int second = 0;
        for (const PCurve& pc : ed.pcurves) second += (pc.face == f && pc.seamSecond);
        if (second != 1)
          problem(name + ": seam on face " + std::to_string(f + 1) + " needs exactly one pcurve marked seamSecond");
      }
    }
  }

  void checkEnds(const std::string& what, const ModelEdge& ed, const Vec3& a, const Vec3& b, double tol) {
    const double t0 = tolerance({tol, vertexTol(ed.v0)}), t1 = tolerance({tol, vertexTol(ed.v1)});
    const double d0 = (a - m_.vertices[ed.v0].p).norm(), d1 = (b - m_.vertices[ed.v1].p).norm();
    if (!(d0 <= t0)) defect(what + ": start is " + fmt(d0) + " from vertex " + std::to_string(ed.v0 + 1));
    if (!(d1 <= t1)) defect(what + ": end is " + fmt(d1) + " from vertex " + std::to_string(ed.v1 + 1));
  }

  /// The pcurve of a use when all references are valid for face f, else null.
  const PCurve* usePCurve(int f, const EdgeUse& u, const std::string& name) {
    if (!inRange(u.edge, m_.edges)) { problem(name + ": edge reference out of range"); return nullptr; }
    const ModelEdge& ed = m_.edges[u.edge];
    const std::string en = "edge " + std::to_string(u.edge + 1);
    if (!inRange(u.pcurve, ed.pcurves)) { problem(name + ": " + en + " has no pcurve " + std::to_string(u.pcurve + 1)); return nullptr; }
    const PCurve& pc = ed.pcurves[u.pcurve];
    if (pc.face != f) { problem(name + ": pcurve " + std::to_string(u.pcurve + 1) + " of " + en + " is not on this face"); return nullptr; }
    if (std::find(ed.faces.begin(), ed.faces.end(), f) == ed.faces.end())
      defect(name + ": " + en + " does not list this face");
    return pc.curve ? &pc : nullptr;
  }

  void checkFace(int f) {
    const ModelFace& face = m_.faces[f];
    const std::string name = "face " + std::to_string(f + 1);
    if (!face.surface) problem(name + ": no surface");
    if (face.loops.empty()) problem(name + ": no loops");
    for (size_t l = 0; l < face.loops.size(); ++l) {
      const Loop& loop = face.loops[l];
      const std::string lname = name + " loop " + std::to_string(l + 1);
      if (loop.outer != (l == 0)) defect(lname + (l == 0 ? ": the first loop is not the outer one" : ": a second outer loop"));
      if (loop.uses.empty()) { problem(lname + ": empty"); continue; }
      std::vector<const PCurve*> pcs;
      for (size_t k = 0; k < loop.uses.size(); ++k)
        pcs.push_back(usePCurve(f, loop.uses[k], lname + " use " + std::to_string(k + 1)));
      for (size_t k = 0; k < loop.uses.size(); ++k) {
        const size_t n = (k + 1) % loop.uses.size();
        checkJunction(face, lname + " between uses " + std::to_string(k + 1) + " and " + std::to_string(n + 1),
                      loop.uses[k], pcs[k], loop.uses[n], pcs[n]);
      }
    }
  }

  void checkJunction(const ModelFace& face, const std::string& name, const EdgeUse& a, const PCurve* pa,
                     const EdgeUse& b, const PCurve* pb) {
    if (!pa || !pb) return;
    const ModelEdge& ea = m_.edges[a.edge];
    const ModelEdge& eb = m_.edges[b.edge];
    const int va = a.reversed ? ea.v0 : ea.v1, vb = b.reversed ? eb.v1 : eb.v0;
    if (va != vb) {
      problem(name + ": vertex " + std::to_string(va + 1) + " does not chain to vertex " + std::to_string(vb + 1));
      return;
    }
    if (!face.surface) return;
    const Vec2 ua = pa->curve->point(a.reversed ? pa->t0 : pa->t1);
    const Vec2 ub = pb->curve->point(b.reversed ? pb->t1 : pb->t0);
    const SurfaceDomain dom = face.surface->domain();
    const Vec2 ext = uvExtent(face, dom);
    // A jump by whole periods of a periodic surface is reported too (a Defect when closed in
    // 3D): the face mesher moves each use next to the previous one and finds whether the
    // loop closes (contour/FaceLoops.cpp); a pole without its degenerate edge does not.
    const Vec2 d = ub - ua;
    Vec2 dn = d;  // the jump less whole periods: ubn is ub's copy next to ua
    if (dom.uPeriodic && dom.uPeriod > 0) dn.x() -= dom.uPeriod * std::round(d.x() / dom.uPeriod);
    if (dom.vPeriodic && dom.vPeriod > 0) dn.y() -= dom.vPeriod * std::round(d.y() / dom.vPeriod);
    const Vec2 ubn = ua + dn;
    const Vec2 gap = d.cwiseAbs();
    const Vec3 sa = face.surface->point(ua), sb = face.surface->point(ubn), sm = face.surface->point(0.5 * (ua + ubn));
    const double d3 = std::max({(sb - sa).norm(), (sm - sa).norm(), (sb - sm).norm()});
    const double tol = tolerance({ea.tolerance, eb.tolerance, face.tolerance, vertexTol(va)});
    const bool uvOk = gap.x() <= kUvGapRatio * ext.x() && gap.y() <= kUvGapRatio * ext.y();
    if (!(d3 <= tol) || !uvOk) {
      defect(name + ": open by (" + fmt(gap.x()) + ", " + fmt(gap.y()) + ") in (u,v), " + fmt(d3) +
                 " in 3D (tolerance " + fmt(tol) + ")",
             d3 <= tol ? ModelIssue::Level::Defect : ModelIssue::Level::Gap);
      const auto offPeriod = [](double g, bool periodic, double period) {
        return periodic && period > 0 ? std::abs(g - period * std::round(g / period)) : g;
      };
      out_.back().uvGapShare = std::max(offPeriod(gap.x(), dom.uPeriodic, dom.uPeriod) / ext.x(),
                                        offPeriod(gap.y(), dom.vPeriodic, dom.vPeriod) / ext.y());
    }
  }

  static Vec2 uvExtent(const ModelFace& face, const SurfaceDomain& dom) {
    const auto usable = [](double e, double fallback) {
      if (std::isfinite(e) && e > 0) return e;
      return (std::isfinite(fallback) && fallback > 0 && fallback < 1e12) ? fallback : 1.0;
    };
    const Vec2 s = face.uvBounds.size();
    return Vec2(usable(s.x(), dom.u1 - dom.u0), usable(s.y(), dom.v1 - dom.v0));
  }

  void checkShell(int s) {
    const ModelShell& sh = m_.shells[s];
    const std::string name = "shell " + std::to_string(s + 1);
    std::map<int, int> uses;
    for (const FaceUse& fu : sh.faces) {
      if (!inRange(fu.face, m_.faces)) { problem(name + ": face reference out of range"); continue; }
      for (const Loop& l : m_.faces[fu.face].loops)
        for (const EdgeUse& u : l.uses)
          if (inRange(u.edge, m_.edges)) ++uses[u.edge];
    }
    if (!sh.closed) return;
    for (const auto& [e, n] : uses) {
      const ModelEdge& ed = m_.edges[e];
      if (ed.degenerate || ed.seam || n == 2) continue;
      defect(name + ": closed, but edge " + std::to_string(e + 1) + " is used " + std::to_string(n) + " times");
    }
  }

  void checkSolid(int s) {
    const ModelSolid& so = m_.solids[s];
    const std::string name = "solid " + std::to_string(s + 1);
    if (!inRange(so.outerShell, m_.shells)) problem(name + ": outer shell reference out of range");
    for (int v : so.voidShells)
      if (!inRange(v, m_.shells)) problem(name + ": void shell reference out of range");
    for (const EmbeddedFace& e : so.embedded)
      if (!inRange(e.face, m_.faces)) problem(name + ": embedded face reference out of range");
  }
};

}  // namespace

std::vector<int> Model::solidFaces(int s) const {
  const ModelSolid& so = solids.at(static_cast<std::size_t>(s));
  std::vector<int> shellIds = so.voidShells;
  shellIds.push_back(so.outerShell);
  std::vector<int> out;
  for (const int sh : shellIds)
    if (sh >= 0 && static_cast<std::size_t>(sh) < shells.size())
      for (const FaceUse& u : shells[static_cast<std::size_t>(sh)].faces) out.push_back(u.face);
  return out;
}

std::vector<int> Model::solidBoundaryFaces(int s) const {
  std::vector<int> out = solidFaces(s);
  for (const EmbeddedFace& e : solids.at(static_cast<std::size_t>(s)).embedded) out.push_back(e.face);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<ModelIssue> Model::check() const { return Validator(*this).run(); }

std::vector<std::string> Model::validate() const {
  std::vector<std::string> out;
  for (ModelIssue& i : check()) out.push_back(std::move(i.message));
  return out;
}

}  // namespace aniso
