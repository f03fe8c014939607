// A face loop written as several edges that are each closed on their own (two rim circles
// of a cylinder in one EDGE_LOOP, no seam between them): no two consecutive edges share a
// vertex, so the loop does not chain. Each such edge is a loop by itself: the wire is split
// into one wire per edge, for ShapeFix_Face to add what the face then lacks (the seam).
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <vector>

#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {

namespace {

bool closedOnItself(const TopoDS_Edge& e) {
  TopoDS_Vertex a, b;
  TopExp::Vertices(e, a, b);
  return !a.IsNull() && a.IsSame(b) && !BRep_Tool::Degenerated(e);
}

/// The wire's edges in order when it has two or more, each closed on itself, none sharing a
/// vertex with the next; else empty.
std::vector<TopoDS_Edge> separateClosedEdges(const TopoDS_Wire& wire) {
  std::vector<TopoDS_Edge> edges;
  for (TopoDS_Iterator it(wire); it.More(); it.Next()) {
    if (it.Value().ShapeType() != TopAbs_EDGE) return {};
    const TopoDS_Edge e = TopoDS::Edge(it.Value());
    if (!closedOnItself(e)) return {};
    edges.push_back(e);
  }
  if (edges.size() < 2) return {};
  for (size_t i = 0; i < edges.size(); ++i) {
    TopoDS_Vertex a, b;
    TopExp::Vertices(edges[i], a, b);
    TopoDS_Vertex c, d;
    TopExp::Vertices(edges[(i + 1) % edges.size()], c, d);
    if (a.IsSame(c)) return {};
  }
  return edges;
}

}  // namespace

int splitLoopsOfClosedEdges(const TopoDS_Shape& shape, ShapeBuild_ReShape& context) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  BRep_Builder b;
  int changed = 0;
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face face = TopoDS::Face(faces(i));
    bool split = false;
    for (TopoDS_Iterator w(face); w.More() && !split; w.Next())
      split = w.Value().ShapeType() == TopAbs_WIRE && !separateClosedEdges(TopoDS::Wire(w.Value())).empty();
    if (!split) continue;
    TopoDS_Face out = TopoDS::Face(face.EmptyCopied());
    for (TopoDS_Iterator w(face); w.More(); w.Next()) {
      const std::vector<TopoDS_Edge> edges =
          w.Value().ShapeType() == TopAbs_WIRE ? separateClosedEdges(TopoDS::Wire(w.Value())) : std::vector<TopoDS_Edge>{};
      if (edges.empty()) {
        b.Add(out, w.Value());
        continue;
      }
      for (const TopoDS_Edge& e : edges) {
        TopoDS_Wire one;
        b.MakeWire(one);
        b.Add(one, e);
        one.Closed(true);
        b.Add(out, one.Oriented(w.Value().Orientation()));
      }
    }
    context.Replace(face, out);
    ++changed;
  }
  return changed;
}

}  // namespace aniso::cad::detail
