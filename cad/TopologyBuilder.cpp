// buildTopology: the mesher's Model from an OCCT shape (see TopologyBuilder.h).
//
// Conventions (Model.h's terms):
//  - Ids: TopExp::MapShapes order over the whole shape, 1-based; Model index = id − 1.
//  - ModelEdge: the edge taken FORWARD; v0/v1 = TopExp::Vertices of the FORWARD edge, i.e.
//    the vertices at t0 and t1 of BRep_Tool::Range.
//  - PCurve: on a seam face the pcurve BRep_Tool assigns to the FORWARD edge in the FORWARD
//    face comes first (seamSecond = false), the one of the REVERSED edge second
//    (seamSecond = true).
//  - ModelFace.reversed: the face's orientation as MapShapes first met it is REVERSED, i.e.
//    its normal is −(pu × pv).
//  - Loops and EdgeUse.reversed follow the ORIENTED face (the face as in the map, wires
//    walked with BRepTools_WireExplorer on it): EdgeUse.reversed is the edge occurrence's
//    orientation composed with the face's. For a non-reversed face the face lies on the
//    left of every use in the (u,v) plane (outer loop counter-clockwise, holes clockwise);
//    for a reversed face on the right (outer loop clockwise in (u,v)), which is again
//    "on the left" seen from the oriented normal in 3D. EdgeUse.pcurve is the pcurve of the
//    occurrence in the FORWARD face (orientation = use's XOR face's), see PCurve above.
//  - FaceUse.reversed: the face's orientation as it occurs in the shell (composed from the
//    root of the shape) is REVERSED, i.e. in that shell its normal is −(pu × pv); same
//    meaning as ModelFace.reversed.
//  - Edges with INTERNAL or EXTERNAL orientation in a face get a pcurve on it and do not
//    count for a shell's closedness; an INTERNAL one (an edge embedded in the face, e.g.
//    where a face inside a solid meets its boundary) is also a slit loop of the face
//    (Loop::slit), an EXTERNAL one is in no loop. A face itself met as INTERNAL or
//    EXTERNAL is treated as FORWARD (reversed = false) and is in no ModelShell's faces; an
//    INTERNAL face of a solid's shell is one of the solid's embedded faces (a crack when
//    its shell has no other face: ModelSolid::embedded), a shell of only such faces is
//    neither the outer shell's nor a void shell.
#include "cad/TopologyBuilder.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepClass3d.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include <algorithm>
#include <cmath>
#include <memory>

#include "cad/FalsePole.h"
#include "cad/OcctCurve2d.h"
#include "cad/OcctCurve3d.h"
#include "cad/OcctSurface.h"
#include "cad/detail/OcctConvert.h"
#include "cad/detail/ShapeSummary.h"
#include "cad/detail/SheetShell.h"
#include "mesher/model/ChainLoop.h"
#include "mesher/core/Error.h"

namespace aniso::cad {
namespace {

using detail::occtMessage;

/// The kernel's area or volume that `props` (a BRepGProp call) adds up; 0 when it fails
/// or is not positive (not known).
template <class Props>
double measure(const Props& props) {
  try {
    GProp_GProps g;
    props(g);
    return g.Mass() > 0 ? g.Mass() : 0;
  } catch (const Standard_Failure&) {
    return 0;
  }
}

std::string entityName(const char* kind, int index) {
  return std::string(kind) + " " + std::to_string(index + 1);
}

struct ShapeMaps {
  TopTools_IndexedMapOfShape vertices, edges, faces, shells, solids;

  explicit ShapeMaps(const TopoDS_Shape& shape) {
    TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
    TopExp::MapShapes(shape, TopAbs_EDGE, edges);
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    TopExp::MapShapes(shape, TopAbs_SHELL, shells);
    TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  }
};

/// 0-based index of `s` (any orientation) in `map`; throws when absent.
int indexIn(const TopTools_IndexedMapOfShape& map, const TopoDS_Shape& s, const char* kind) {
  const int i = map.FindIndex(s);
  if (i == 0) throw MeshingError(std::string("a ") + kind + " is missing from the shape's map");
  return i - 1;
}

bool isForwardOrReversed(TopAbs_Orientation o) {
  return o == TopAbs_FORWARD || o == TopAbs_REVERSED;
}

void buildVertices(const ShapeMaps& maps, Model& model) {
  model.vertices.resize(maps.vertices.Extent());
  for (int i = 0; i < maps.vertices.Extent(); ++i) {
    const TopoDS_Vertex& v = TopoDS::Vertex(maps.vertices(i + 1));
    const gp_Pnt p = BRep_Tool::Pnt(v);
    model.vertices[i].p = Vec3(p.X(), p.Y(), p.Z());
    model.vertices[i].tolerance = BRep_Tool::Tolerance(v);
  }
}

void buildEdge(const ShapeMaps& maps, int i, ModelEdge& me) {
  const std::string name = entityName("edge", i);
  const TopoDS_Edge e = TopoDS::Edge(maps.edges(i + 1).Oriented(TopAbs_FORWARD));
  me.degenerate = BRep_Tool::Degenerated(e);
  BRep_Tool::Range(e, me.t0, me.t1);
  me.tolerance = BRep_Tool::Tolerance(e);
  TopoDS_Vertex a, b;
  TopExp::Vertices(e, a, b);
  if (a.IsNull() || b.IsNull()) throw MeshingError(name + ": the edge has no end vertices");
  me.v0 = indexIn(maps.vertices, a, "vertex");
  me.v1 = indexIn(maps.vertices, b, "vertex");
  if (!me.degenerate) me.curve = std::make_shared<OcctCurve3d>(e, name);
}

void buildEdges(const ShapeMaps& maps, Model& model) {
  model.edges.resize(maps.edges.Extent());
  for (int i = 0; i < maps.edges.Extent(); ++i) {
    try {
      buildEdge(maps, i, model.edges[i]);
    } catch (const Standard_Failure& e) {
      throw MeshingError(entityName("edge", i) + ": OCCT failed: " + occtMessage(e));
    }
  }
}

PCurve makePCurve(const TopoDS_Edge& edge, const TopoDS_Face& forwardFace, int face,
                  bool second, const std::string& name) {
  auto curve = std::make_shared<OcctCurve2d>(edge, forwardFace, name);
  PCurve pc;
  pc.face = face;
  pc.t0 = curve->first();
  pc.t1 = curve->last();
  pc.seamSecond = second;
  pc.curve = std::move(curve);
  return pc;
}

/// The pcurves of every edge of face `fi` on it (two on a seam), and the face in the
/// edges' face lists.
void addPCurves(const ShapeMaps& maps, const TopoDS_Face& forwardFace, int fi, Model& model) {
  TopTools_IndexedMapOfShape faceEdges;
  TopExp::MapShapes(forwardFace, TopAbs_EDGE, faceEdges);
  for (int k = 1; k <= faceEdges.Extent(); ++k) {
    const TopoDS_Edge e = TopoDS::Edge(faceEdges(k).Oriented(TopAbs_FORWARD));
    const int ei = indexIn(maps.edges, e, "edge");
    ModelEdge& me = model.edges[ei];
    const std::string name = entityName("edge", ei) + " on " + entityName("face", fi);
    me.faces.push_back(fi);
    me.pcurves.push_back(makePCurve(e, forwardFace, fi, false, name));
    if (BRep_Tool::IsClosed(e, forwardFace)) {
      me.seam = true;
      me.pcurves.push_back(
          makePCurve(TopoDS::Edge(e.Reversed()), forwardFace, fi, true, name + " (seam)"));
    }
  }
}

/// The use of an edge occurrence with orientation `o` (as walked in the oriented face).
EdgeUse makeUse(const ShapeMaps& maps, const Model& model, const TopoDS_Edge& edge,
                TopAbs_Orientation o, int fi, bool faceReversed) {
  EdgeUse use;
  use.edge = indexIn(maps.edges, edge, "edge");
  use.reversed = (o == TopAbs_REVERSED);
  const bool reversedInForwardFace = use.reversed != faceReversed;
  const std::vector<PCurve>& pcs = model.edges[use.edge].pcurves;
  bool seamHere = false;
  for (const PCurve& pc : pcs) seamHere = seamHere || (pc.face == fi && pc.seamSecond);
  for (int k = 0; k < static_cast<int>(pcs.size()); ++k) {
    if (pcs[k].face != fi) continue;
    if (!seamHere || pcs[k].seamSecond == reversedInForwardFace) {
      use.pcurve = k;
      break;
    }
  }
  if (use.pcurve < 0)
    throw MeshingError(entityName("edge", use.edge) + " has no pcurve on " +
                       entityName("face", fi));
  return use;
}

/// The uses of `wire` in walking order (BRepTools_WireExplorer on the oriented face); the
/// stored order when the explorer cannot walk the whole wire (a defective wire, which
/// Model::validate() then reports as not closed).
Loop walkWire(const ShapeMaps& maps, const Model& model, const TopoDS_Wire& wire,
              const TopoDS_Face& face, int fi, bool outer) {
  const bool faceReversed = face.Orientation() == TopAbs_REVERSED;
  Loop loop;
  loop.outer = outer;
  int expected = 0;
  for (TopExp_Explorer x(wire, TopAbs_EDGE); x.More(); x.Next())
    if (isForwardOrReversed(x.Current().Orientation())) ++expected;
  try {
    // The occurrence's orientation is Current().Orientation() (composed with the wire's);
    // WireExplorer::Orientation() is that of the current vertex, unreliable on closed edges.
    for (BRepTools_WireExplorer w(wire, face); w.More(); w.Next()) {
      const TopAbs_Orientation o = w.Current().Orientation();
      if (isForwardOrReversed(o))
        loop.uses.push_back(makeUse(maps, model, w.Current(), o, fi, faceReversed));
    }
  } catch (const Standard_Failure&) {
    loop.uses.clear();  // fall back to the stored order below
  }
  if (static_cast<int>(loop.uses.size()) != expected) {
    loop.uses.clear();
    for (TopExp_Explorer x(wire, TopAbs_EDGE); x.More(); x.Next()) {
      const TopAbs_Orientation o = x.Current().Orientation();
      if (isForwardOrReversed(o))
        loop.uses.push_back(makeUse(maps, model, TopoDS::Edge(x.Current()), o, fi, faceReversed));
    }
    if (!loop.uses.empty()) chainLoopUses(model, loop.uses);
  }
  // false poles left out: the loop is chained across their jumps by whole periods
  try {
    const TopoDS_Face forwardFace = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
    std::vector<EdgeUse> kept;
    for (const EdgeUse& u : loop.uses)
      if (!model.edges[u.edge].degenerate ||
          !falsePole(TopoDS::Edge(maps.edges(u.edge + 1).Oriented(TopAbs_FORWARD)), forwardFace))
        kept.push_back(u);
    // only when an edge other than a seam is left: a loop whose rims OCCT turned into such
    // edges altogether (seen on a lone face of revolution) has nothing to chain them by
    const bool bounded = std::any_of(kept.begin(), kept.end(), [&model](const EdgeUse& u) {
      return !model.edges[u.edge].degenerate && !model.edges[u.edge].seam;
    });
    if (bounded) loop.uses = std::move(kept);
  } catch (const Standard_Failure&) {
    // the loop as walked
  }
  return loop;
}

void buildFace(const ShapeMaps& maps, int fi, Model& model) {
  const std::string name = entityName("face", fi);
  const TopoDS_Face forwardFace = TopoDS::Face(maps.faces(fi + 1).Oriented(TopAbs_FORWARD));
  // A face met as INTERNAL or EXTERNAL (a loose face stored so) has no side: its loops are
  // taken as for FORWARD (composing INTERNAL would make every edge INTERNAL).
  const TopoDS_Face face = isForwardOrReversed(maps.faces(fi + 1).Orientation())
                               ? TopoDS::Face(maps.faces(fi + 1))
                               : forwardFace;
  ModelFace& mf = model.faces[fi];
  try {
    mf.surface = std::make_shared<OcctSurface>(forwardFace, name);
  } catch (const MeshingError&) {
    // no usable surface (an unbounded one with no boundary, none at all): the face stays
    // without one, Model::check reports it unusable and the pipeline leaves it out
    mf.surface = nullptr;
  }
  mf.reversed = face.Orientation() == TopAbs_REVERSED;
  mf.tolerance = BRep_Tool::Tolerance(face);
  mf.cadArea = measure([&](GProp_GProps& g) { BRepGProp::SurfaceProperties(forwardFace, g); });
  double u0, u1, v0, v1;
  BRepTools::UVBounds(forwardFace, u0, u1, v0, v1);
  if (u0 <= u1 && v0 <= v1) {
    mf.uvBounds.add(Vec2(u0, v0));
    mf.uvBounds.add(Vec2(u1, v1));
  }
  addPCurves(maps, forwardFace, fi, model);

  const TopoDS_Wire outer = BRepTools::OuterWire(face);
  if (!outer.IsNull()) mf.loops.push_back(walkWire(maps, model, outer, face, fi, true));
  for (TopExp_Explorer x(face, TopAbs_WIRE); x.More(); x.Next()) {
    if (x.Current().IsSame(outer) || !isForwardOrReversed(x.Current().Orientation())) continue;
    Loop loop = walkWire(maps, model, TopoDS::Wire(x.Current()), face, fi, false);
    if (!loop.uses.empty()) mf.loops.push_back(std::move(loop));
  }
  // Each INTERNAL edge: a slit, walked there and back (Loop::slit).
  TopTools_IndexedMapOfShape slits;
  for (TopExp_Explorer x(face, TopAbs_EDGE); x.More(); x.Next())
    if (x.Current().Orientation() == TopAbs_INTERNAL && !BRep_Tool::Degenerated(TopoDS::Edge(x.Current())))
      slits.Add(x.Current().Oriented(TopAbs_FORWARD));
  const bool faceReversed = face.Orientation() == TopAbs_REVERSED;
  for (int k = 1; k <= slits.Extent(); ++k) {
    const TopoDS_Edge e = TopoDS::Edge(slits(k));
    Loop loop;
    loop.slit = true;
    loop.uses.push_back(makeUse(maps, model, e, TopAbs_FORWARD, fi, faceReversed));
    loop.uses.push_back(makeUse(maps, model, e, TopAbs_REVERSED, fi, faceReversed));
    mf.loops.push_back(std::move(loop));
  }
}

void buildFaces(const ShapeMaps& maps, Model& model) {
  model.faces.resize(maps.faces.Extent());
  for (int i = 0; i < maps.faces.Extent(); ++i) {
    try {
      buildFace(maps, i, model);
    } catch (const Standard_Failure& e) {
      throw MeshingError(entityName("face", i) + ": OCCT failed: " + occtMessage(e));
    }
  }
}

void buildShell(const ShapeMaps& maps, int si, Model& model) {
  ModelShell& ms = model.shells[si];
  std::vector<int> uses(model.edges.size(), 0);
  for (TopExp_Explorer f(maps.shells(si + 1), TopAbs_FACE); f.More(); f.Next()) {
    if (!isForwardOrReversed(f.Current().Orientation())) continue;  // inside the material: ModelSolid::embedded
    ms.faces.push_back({indexIn(maps.faces, f.Current(), "face"),
                        f.Current().Orientation() == TopAbs_REVERSED});
    for (TopExp_Explorer e(f.Current(), TopAbs_EDGE); e.More(); e.Next()) {
      if (!isForwardOrReversed(e.Current().Orientation())) continue;
      const int ei = indexIn(maps.edges, e.Current(), "edge");
      if (!model.edges[ei].degenerate && !model.edges[ei].seam) ++uses[ei];
    }
  }
  ms.closed = !ms.faces.empty();
  for (int n : uses) ms.closed = ms.closed && (n == 0 || n == 2);
}

void buildShells(const ShapeMaps& maps, Model& model) {
  model.shells.resize(maps.shells.Extent());
  for (int i = 0; i < maps.shells.Extent(); ++i) {
    try {
      buildShell(maps, i, model);
    } catch (const Standard_Failure& e) {
      throw MeshingError(entityName("shell", i) + ": OCCT failed: " + occtMessage(e));
    }
  }
}

double boxDiagonal(const TopoDS_Shape& s) {
  Bnd_Box b;
  BRepBndLib::Add(s, b, false);
  return b.IsVoid() ? 0.0 : std::sqrt(b.SquareExtent());
}

void buildSolid(const ShapeMaps& maps, int si, Model& model,
                const std::function<std::string(const TopoDS_Shape&, int)>& solidName,
                const std::function<double(const TopoDS_Shape&)>& solidVolume) {
  const TopoDS_Solid& solid = TopoDS::Solid(maps.solids(si + 1));
  ModelSolid& ms = model.solids[si];
  ms.name = solidName ? solidName(solid, si + 1) : "SOLID" + std::to_string(si + 1);
  std::vector<TopoDS_Shape> shells;
  for (TopoDS_Iterator it(solid); it.More(); it.Next())
    if (it.Value().ShapeType() == TopAbs_SHELL) shells.push_back(it.Value());
  if (shells.empty()) throw MeshingError(entityName("solid", si) + ": the solid has no shell");
  TopoDS_Shape outer = BRepClass3d::OuterShell(solid);
  if (outer.IsNull()) {
    // No shell classifies as outer (open shells): take the largest.
    double best = -1;
    for (const TopoDS_Shape& s : shells) {
      const double d = boxDiagonal(s);
      if (d > best) {
        best = d;
        outer = s;
      }
    }
  }
  ms.outerShell = indexIn(maps.shells, outer, "shell");
  ms.cadVolume = std::max(0.0, solidVolume(solid));
  for (const TopoDS_Shape& s : shells) {
    // Faces met INTERNAL lie inside the material. A shell made only of them encloses no
    // volume (OCCT's way of keeping a face inside a solid, e.g. after a general fuse of
    // the solid with the face): a zero-thickness shell, i.e. a crack; INTERNAL faces in a
    // shell that bounds the solid are a bonded interface.
    // An open void shell that is a sheet (detail/SheetShell.h) is a crack too, whatever the
    // orientation its faces are stored with.
    const int shellIndex = indexIn(maps.shells, s, "shell");
    const bool sheet = !s.IsSame(outer) && !model.shells[shellIndex].closed && detail::isSheetShell(s);
    std::vector<int> internal;
    bool bounding = false;
    for (TopExp_Explorer f(s, TopAbs_FACE); f.More(); f.Next()) {
      if (f.Current().Orientation() == TopAbs_INTERNAL || (sheet && f.Current().Orientation() != TopAbs_EXTERNAL))
        internal.push_back(indexIn(maps.faces, f.Current(), "face"));
      else bounding = bounding || f.Current().Orientation() != TopAbs_EXTERNAL;
    }
    for (const int f : internal) {
      const bool seen = std::any_of(ms.embedded.begin(), ms.embedded.end(), [&](const EmbeddedFace& e) { return e.face == f; });
      if (!seen) ms.embedded.push_back({f, !bounding});
    }
    if (!s.IsSame(outer) && bounding) ms.voidShells.push_back(shellIndex);
  }
}

void buildSolids(const ShapeMaps& maps, Model& model,
                 const std::function<std::string(const TopoDS_Shape&, int)>& solidName,
                 const std::function<double(const TopoDS_Shape&)>& solidVolume) {
  model.solids.resize(maps.solids.Extent());
  for (int i = 0; i < maps.solids.Extent(); ++i) {
    try {
      buildSolid(maps, i, model, solidName, solidVolume);
    } catch (const Standard_Failure& e) {
      throw MeshingError(entityName("solid", i) + ": OCCT failed: " + occtMessage(e));
    }
  }
}

/// The shape's box; when a face has no usable surface (an unbounded plane without a
/// boundary spans 1e100), the box of the other faces, the edges and the vertices, so that
/// the sizes relative to the model's diagonal stay those of what is meshed.
Box3 boundingBox(const TopoDS_Shape& shape, const ShapeMaps& maps, const Model& model) {
  Box3 box;
  Bnd_Box b;
  const bool allUsable = std::all_of(model.faces.begin(), model.faces.end(), [](const ModelFace& f) { return f.surface != nullptr; });
  if (allUsable) {
    BRepBndLib::Add(shape, b, false);
  } else {
    for (int i = 1; i <= maps.faces.Extent(); ++i)
      if (model.faces[static_cast<std::size_t>(i - 1)].surface) BRepBndLib::Add(maps.faces(i), b, false);
    for (int i = 1; i <= maps.edges.Extent(); ++i) BRepBndLib::Add(maps.edges(i), b, false);
    for (int i = 1; i <= maps.vertices.Extent(); ++i) BRepBndLib::Add(maps.vertices(i), b, false);
  }
  if (b.IsVoid()) return box;
  b.SetGap(0.0);
  double x0, y0, z0, x1, y1, z1;
  b.Get(x0, y0, z0, x1, y1, z1);
  box.add(Vec3(x0, y0, z0));
  box.add(Vec3(x1, y1, z1));
  return box;
}

}  // namespace

Model buildTopology(const TopoDS_Shape& shape,
                    const std::function<std::string(const TopoDS_Shape&, int)>& solidName,
                    const std::function<double(const TopoDS_Shape&)>& solidVolume) {
  Model model;
  try {
    const ShapeMaps maps(shape);
    buildVertices(maps, model);
    buildEdges(maps, model);
    buildFaces(maps, model);
    buildShells(maps, model);
    buildSolids(maps, model, solidName, solidVolume ? solidVolume : detail::accurateVolume);
    model.bbox = boundingBox(shape, maps, model);
  } catch (const Standard_Failure& e) {
    throw MeshingError("building the topology: OCCT failed: " + occtMessage(e));
  }
  return model;
}

}  // namespace aniso::cad
