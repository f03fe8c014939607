#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp_Face.hxx>
#include <Geom2d_Curve.hxx>
#include <BRepTools.hxx>
#include <BRepTools_ReShape.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {
namespace {

/// A fin holds at most this fraction of its solid's volume...
constexpr double kFinVolumeRel = 1e-3;
/// ...and is on average at most this fraction of the model's diagonal thick (2 V / A).
constexpr double kFinThicknessRel = 1e-3;
/// A flood that reaches more faces than this is the solid's body, not a fin.
constexpr int kMaxFinFaces = 64;

/// The faces on one side of a contact edge, up to the faces they end on where the fin runs
/// into a wall; `caps` receives the edges of those walls' faces along the fin's cross-section
/// (an inner wire, or a notch of the outer wire pinched at an end of the contact edge).
/// None when the flood grows past kMaxFinFaces.
struct Lobe {
  TopTools_IndexedMapOfShape faces;
  std::vector<std::pair<TopoDS_Face, TopoDS_Shape>> caps;  // (wall face, edge)
};

/// Does the wire pass a vertex of the contact edges more than once?
bool pinchedAtContact(const TopoDS_Wire& w, const TopTools_IndexedMapOfShape& contactVertices) {
  TopTools_IndexedDataMapOfShapeListOfShape vertexEdges;
  TopExp::MapShapesAndAncestors(w, TopAbs_VERTEX, TopAbs_EDGE, vertexEdges);
  for (int i = 1; i <= vertexEdges.Extent(); ++i) {
    if (!contactVertices.Contains(vertexEdges.FindKey(i))) continue;
    TopTools_IndexedMapOfShape distinct;
    for (const TopoDS_Shape& e : vertexEdges(i)) distinct.Add(e);
    if (distinct.Extent() > 2) return true;
  }
  return false;
}

/// The face's outer wire: the one enclosing the largest area on its own (BRepTools::OuterWire
/// took a hole touching the outer wire at a point for it).
TopoDS_Wire outerWireOf(const TopoDS_Face& f) {
  TopoDS_Wire best;
  double largest = -1;
  for (TopoDS_Iterator w(f); w.More(); w.Next()) {
    if (w.Value().ShapeType() != TopAbs_WIRE) continue;
    TopoDS_Face alone = TopoDS::Face(f.EmptyCopied());
    BRep_Builder().Add(alone, w.Value());
    if (const double a = std::abs(shapeArea(alone)); a > largest) largest = a, best = TopoDS::Wire(w.Value());
  }
  return best;
}

bool holds(const TopoDS_Shape& wire, const TopoDS_Shape& e) {
  for (TopExp_Explorer y(wire, TopAbs_EDGE); y.More(); y.Next())
    if (y.Current().IsSame(e)) return true;
  return false;
}

std::optional<Lobe> lobeFrom(const TopoDS_Face& start, const TopTools_IndexedMapOfShape& contact,
                             const TopTools_IndexedMapOfShape& contactVertices,
                             const TopTools_IndexedDataMapOfShapeListOfShape& edgeFaces) {
  Lobe lobe;
  lobe.faces.Add(start);
  for (int k = 1; k <= lobe.faces.Extent(); ++k) {
    const TopoDS_Face face = TopoDS::Face(lobe.faces(k));
    for (TopExp_Explorer x(face, TopAbs_EDGE); x.More(); x.Next()) {
      const TopoDS_Shape& e = x.Current();
      if (contact.Contains(e) || !edgeFaces.Contains(e)) continue;
      for (const TopoDS_Shape& other : edgeFaces.FindFromKey(e)) {
        if (other.IsSame(face) || lobe.faces.Contains(other)) continue;
        const TopoDS_Face g = TopoDS::Face(other);
        const TopoDS_Wire outer = outerWireOf(g);
        if (holds(outer, e) && !pinchedAtContact(outer, contactVertices)) {
          lobe.faces.Add(g);
          if (lobe.faces.Extent() > kMaxFinFaces) return std::nullopt;
          continue;
        }
        bool known = false;  // a wall the fin runs into: e is on its cross-section there
        for (const auto& [cf, ce] : lobe.caps) known = known || (cf.IsSame(g) && ce.IsSame(e));
        if (!known) lobe.caps.push_back({g, e});
      }
    }
  }
  for (const auto& [g, e] : lobe.caps)
    if (lobe.faces.Contains(g)) return std::nullopt;  // a face both in the lobe and capped by it
  return lobe;
}

/// Two faces of a fin close a cusp at a contact edge: their outward normals at its middle
/// are opposed to within kFinCuspAngle.
constexpr double kFinCuspAngle = 0.0523598775598;  // 3°

bool closeACusp(const TopoDS_Face& a, const TopoDS_Face& b, const TopoDS_Edge& e) {
  double t0 = 0, t1 = 0;
  const auto normal = [&](const TopoDS_Face& f, gp_Vec& n) {
    const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(e, f, t0, t1);
    if (c.IsNull()) return false;
    const gp_Pnt2d uv = c->Value(0.5 * (t0 + t1));
    gp_Pnt p;
    BRepGProp_Face(f).Normal(uv.X(), uv.Y(), p, n);  // follows the face's orientation: outward
    return n.Magnitude() > 0;
  };
  gp_Vec na, nb;
  if (!normal(a, na) || !normal(b, nb)) return false;
  return na.Normalized().Dot(nb.Normalized()) < -std::cos(kFinCuspAngle);
}


}  // namespace

namespace {

/// One fin off the solid (the first found), or none.
std::optional<FinRemoval> withoutOneFin(const TopoDS_Shape& solid, const std::vector<TopoDS_Shape>& contactEdges,
                                        double diag) {
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  TopTools_IndexedMapOfShape contact, contactVertices;
  for (const TopoDS_Shape& e : contactEdges) contact.Add(e), TopExp::MapShapes(e, TopAbs_VERTEX, contactVertices);
  const double volume = std::abs(solidVolume(solid));
  TopTools_IndexedMapOfShape tried;
  for (const TopoDS_Shape& e : contactEdges) {
    if (!edgeFaces.Contains(e)) continue;
    for (const TopoDS_Shape& f : edgeFaces.FindFromKey(e)) {
      if (tried.Contains(f)) continue;
      tried.Add(f);  // (a lobe from the body may run into the fin through a wall's hole: only the start is done)
      const std::optional<Lobe> lobe = lobeFrom(TopoDS::Face(f), contact, contactVertices, edgeFaces);
      if (!lobe) continue;
      // the lobe must leave two faces at each of its contact edges and close a cusp with
      // the two it has there
      bool oneSide = true, cusp = true;
      for (int k = 1; k <= contact.Extent() && oneSide; ++k) {
        std::vector<TopoDS_Face> in;
        for (const TopoDS_Shape& g : edgeFaces.FindFromKey(contact(k)))
          if (lobe->faces.Contains(g)) in.push_back(TopoDS::Face(g));
        oneSide = in.empty() || in.size() == 2;
        if (in.size() == 2) cusp = cusp && closeACusp(in[0], in[1], TopoDS::Edge(contact(k)));
      }
      if (!oneSide || !cusp) continue;
      // the solid without the lobe, the walls' faces without the fin's cross-section
      Handle(BRepTools_ReShape) reshape = new BRepTools_ReShape;
      for (int k = 1; k <= lobe->faces.Extent(); ++k) reshape->Remove(lobe->faces(k));
      TopTools_IndexedMapOfShape capped;
      for (const auto& [g, e] : lobe->caps) capped.Add(g);
      BRep_Builder b;
      for (int k = 1; k <= capped.Extent(); ++k) {
        const TopoDS_Face g = TopoDS::Face(capped(k));
        const auto isCap = [&](const TopoDS_Shape& e) {
          for (const auto& [cf, ce] : lobe->caps)
            if (cf.IsSame(g) && ce.IsSame(e)) return true;
          return false;
        };
        TopoDS_Face filled = TopoDS::Face(g.EmptyCopied());
        for (TopoDS_Iterator w(g); w.More(); w.Next()) {
          if (w.Value().ShapeType() != TopAbs_WIRE) {
            b.Add(filled, w.Value());
            continue;
          }
          TopoDS_Wire kept;
          b.MakeWire(kept);
          int edges = 0, left = 0;
          for (TopoDS_Iterator e(w.Value()); e.More(); e.Next(), ++edges)
            if (!isCap(e.Value())) b.Add(kept, e.Value()), ++left;
          if (left == 0) continue;  // the fin's cross-section as a hole: filled
          if (left == edges) {
            b.Add(filled, w.Value());
            continue;
          }
          kept.Closed(true);  // the notch taken out: the wire runs past the pinch
          b.Add(filled, kept.Oriented(w.Value().Orientation()));
        }
        reshape->Replace(g, filled);
      }
      const TopoDS_Shape out = reshape->Apply(solid);
      if (out.IsNull() || out.ShapeType() != TopAbs_SOLID || !BRepCheck_Analyzer(out).IsValid()) continue;
      bool closed = true;
      for (TopExp_Explorer s(out, TopAbs_SHELL); s.More(); s.Next()) closed = closed && BRep_Tool::IsClosed(s.Current());
      if (!closed) continue;
      const double removed = volume - std::abs(solidVolume(out));
      if (!(removed > 0) || removed > kFinVolumeRel * volume) continue;
      double area = 0;
      for (int k = 1; k <= lobe->faces.Extent(); ++k) area += shapeArea(lobe->faces(k));
      const double thickness = 2 * removed / area;
      if (thickness > kFinThicknessRel * diag) continue;
      return FinRemoval{out, removed, thickness, reshape->History()};
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<FinRemoval> withoutCuspFins(const TopoDS_Shape& solid, const std::vector<TopoDS_Shape>& contactEdges,
                                          double diag) {
  std::optional<FinRemoval> all;
  // each fin taken off leaves its contact edges between two faces: bounded by their number
  for (std::size_t round = 0; round < contactEdges.size(); ++round) {
    const TopoDS_Shape current = all ? all->solid : solid;
    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(current, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    std::vector<TopoDS_Shape> left;  // the contact edges still between four faces
    for (const TopoDS_Shape& e : contactEdges) {
      if (!edgeFaces.Contains(e)) continue;
      TopTools_IndexedMapOfShape distinct;
      for (const TopoDS_Shape& f : edgeFaces.FindFromKey(e)) distinct.Add(f);
      if (distinct.Extent() == 4) left.push_back(e);
    }
    std::optional<FinRemoval> one = left.empty() ? std::nullopt : withoutOneFin(current, left, diag);
    if (!one) break;
    if (!all) {
      all = std::move(one);
      continue;
    }
    all->solid = one->solid;
    all->thickness = std::max(all->thickness, one->thickness);
    all->volume += one->volume;
    all->history->Merge(one->history);
  }
  return all;
}

}  // namespace aniso::cad::detail
