#include <BOPAlgo_Builder.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <ElSLib.hxx>
#include <Geom_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Lin.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "cad/detail/FaceTags.h"
#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {
namespace {

/// Axes within this angle (radians) are parallel; a cylinder's axis this close to its
/// plane's direction lies along the plane.
constexpr double kParallelAngle = 1e-6;
/// Surfaces touch when their gap along the contact is below this fraction of the solid's
/// diagonal, or the faces' tolerance when larger.
constexpr double kContactRel = 1e-7;
/// Points along a contact line classified in both faces, to find where it lies on both.
constexpr int kContactSamples = 256;
/// Bisection steps refining each end of a contact run.
constexpr int kEndBisections = 40;
/// A run shorter than this fraction of the diagonal is not imprinted.
constexpr double kMinRunRel = 1e-4;
/// The imprinted edges' pieces between four faces must cover each contact edge but this
/// fraction of its length.
constexpr double kCoveredRel = 1e-6;
/// The imprinted solid must keep its volume to this fraction.
constexpr double kImprintVolumeRel = 1e-5;

/// The line along which two analytic surfaces of one solid touch from outside, when they
/// do: two cylinders with parallel axes as far apart as their radii add up (or differ), or
/// a cylinder whose axis runs along a plane at its radius.
std::optional<gp_Lin> contactLine(const BRepAdaptor_Surface& a, const BRepAdaptor_Surface& b, double tol) {
  if (a.GetType() == GeomAbs_Cylinder && b.GetType() == GeomAbs_Cylinder) {
    const gp_Cylinder ca = a.Cylinder(), cb = b.Cylinder();
    const gp_Dir d = ca.Axis().Direction();
    if (!d.IsParallel(cb.Axis().Direction(), kParallelAngle)) return std::nullopt;
    // the vector between the axes, perpendicular to them
    gp_Vec v(ca.Location(), cb.Location());
    v -= gp_Vec(d) * v.Dot(gp_Vec(d));
    const double dist = v.Magnitude(), ra = ca.Radius(), rb = cb.Radius();
    if (dist <= tol) return std::nullopt;  // coaxial
    const gp_Vec u = v / dist;
    if (std::abs(dist - (ra + rb)) <= tol) return gp_Lin(ca.Location().Translated(u * ra), d);
    if (std::abs(dist - std::abs(ra - rb)) <= tol)  // one inside the other, touching
      return ra > rb ? gp_Lin(ca.Location().Translated(u * ra), d) : gp_Lin(ca.Location().Translated(-u * ra), d);
    return std::nullopt;
  }
  if (a.GetType() == GeomAbs_Plane && b.GetType() == GeomAbs_Cylinder) return contactLine(b, a, tol);
  if (a.GetType() == GeomAbs_Cylinder && b.GetType() == GeomAbs_Plane) {
    const gp_Cylinder c = a.Cylinder();
    const gp_Pln p = b.Plane();
    const gp_Dir n = p.Axis().Direction(), d = c.Axis().Direction();
    if (std::abs(n.Dot(d)) > kParallelAngle) return std::nullopt;
    const double h = gp_Vec(p.Location(), c.Location()).Dot(gp_Vec(n));
    if (std::abs(std::abs(h) - c.Radius()) > tol) return std::nullopt;
    return gp_Lin(c.Location().Translated(-gp_Vec(n) * h), d);
  }
  return std::nullopt;
}

/// Where the point of the surface lies in its face.
TopAbs_State stateIn(const TopoDS_Face& f, const BRepAdaptor_Surface& s, const gp_Pnt& p, double tol) {
  double u = 0, v = 0;
  if (s.GetType() == GeomAbs_Cylinder) {
    ElSLib::Parameters(s.Cylinder(), p, u, v);  // u in [0, 2π): moved into the face's period
    double u0, u1, v0, v1;
    BRepTools::UVBounds(f, u0, u1, v0, v1);
    u += 2 * M_PI * std::floor((u0 - u) / (2 * M_PI) + 1);
    if (u - 2 * M_PI >= u0) u -= 2 * M_PI;
  } else {
    ElSLib::Parameters(s.Plane(), p, u, v);
  }
  return BRepClass_FaceClassifier(f, gp_Pnt2d(u, v), tol).State();
}
bool onFace(const TopoDS_Face& f, const BRepAdaptor_Surface& s, const gp_Pnt& p, double tol) {
  const TopAbs_State st = stateIn(f, s, p, tol);
  return st == TopAbs_IN || st == TopAbs_ON;
}
bool inFace(const TopoDS_Face& f, const BRepAdaptor_Surface& s, const gp_Pnt& p, double tol) {
  return stateIn(f, s, p, tol) == TopAbs_IN;
}

/// Do the faces share a straight edge on the line (a tangent joint: a fillet running into
/// its plane), where they meet as any two neighbours do?
bool joinedAlong(const TopoDS_Face& a, const TopoDS_Face& b, const gp_Lin& line, double tol) {
  TopTools_IndexedMapOfShape edgesOfB;
  TopExp::MapShapes(b, TopAbs_EDGE, edgesOfB);
  for (TopExp_Explorer x(a, TopAbs_EDGE); x.More(); x.Next()) {
    if (!edgesOfB.Contains(x.Current())) continue;
    const TopoDS_Edge& e = TopoDS::Edge(x.Current());
    if (BRep_Tool::Degenerated(e)) continue;
    double t0 = 0, t1 = 0;
    const Handle(Geom_Curve) c = BRep_Tool::Curve(e, t0, t1);
    if (c.IsNull()) continue;
    if (line.Distance(c->Value(0.5 * (t0 + t1))) <= tol + BRep_Tool::Tolerance(e)) return true;
  }
  return false;
}

/// The stretches of the line (within `box`, one face's) lying on both faces.
std::vector<std::pair<gp_Pnt, gp_Pnt>> contactRuns(const gp_Lin& line, const TopoDS_Face& fa,
                                                    const BRepAdaptor_Surface& sa, const TopoDS_Face& fb,
                                                    const BRepAdaptor_Surface& sb, const Bnd_Box& box, double tol,
                                                    double minRun) {
  // the line's parameters over the box's corners
  double xmin, ymin, zmin, xmax, ymax, zmax;
  box.Get(xmin, ymin, zmin, xmax, ymax, zmax);
  double t0 = 1e300, t1 = -1e300;
  for (const double x : {xmin, xmax})
    for (const double y : {ymin, ymax})
      for (const double z : {zmin, zmax}) {
        const double t = gp_Vec(line.Location(), gp_Pnt(x, y, z)).Dot(gp_Vec(line.Direction()));
        t0 = std::min(t0, t), t1 = std::max(t1, t);
      }
  const auto at = [&](double t) { return line.Location().Translated(gp_Vec(line.Direction()) * t); };
  const auto both = [&](double t) { return onFace(fa, sa, at(t), tol) && onFace(fb, sb, at(t), tol); };
  const auto edgeBetween = [&](double in, double out) {  // the last parameter on both faces
    for (int k = 0; k < kEndBisections; ++k) {
      const double mid = 0.5 * (in + out);
      (both(mid) ? in : out) = mid;
    }
    return in;
  };
  std::vector<std::pair<gp_Pnt, gp_Pnt>> runs;
  const double step = (t1 - t0) / kContactSamples;
  std::optional<double> start;
  bool prev = false;
  for (int i = 0; i <= kContactSamples; ++i) {
    const double t = t0 + i * step;
    const bool now = both(t);
    if (now && !prev) start = i == 0 ? t : edgeBetween(t, t - step);
    if (!now && prev && start) {
      const double end = edgeBetween(t - step, t);
      if (end - *start > minRun) runs.push_back({at(*start), at(end)});
      start.reset();
    }
    prev = now;
  }
  if (prev && start && t1 - *start > minRun) runs.push_back({at(*start), at(t1)});
  return runs;
}

/// The edges along which two faces of the solid touch without sharing an edge there.
std::vector<TopoDS_Edge> contactEdges(const TopoDS_Shape& solid, double diag) {
  std::vector<TopoDS_Face> faces;
  std::vector<BRepAdaptor_Surface> surfaces;
  std::vector<Bnd_Box> boxes;
  TopTools_IndexedMapOfShape all;  // each face once
  TopExp::MapShapes(solid, TopAbs_FACE, all);
  for (int k = 1; k <= all.Extent(); ++k) {
    const TopoDS_Face f = TopoDS::Face(all(k));
    BRepAdaptor_Surface s(f, false);
    if (s.GetType() != GeomAbs_Cylinder && s.GetType() != GeomAbs_Plane) continue;
    faces.push_back(f);
    surfaces.push_back(s);
    boxes.emplace_back();
    BRepBndLib::Add(f, boxes.back());
  }
  std::vector<TopoDS_Edge> out;
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      if (surfaces[i].GetType() == GeomAbs_Plane && surfaces[j].GetType() == GeomAbs_Plane) continue;
      const double tol =
          std::max({kContactRel * diag, BRep_Tool::Tolerance(faces[i]), BRep_Tool::Tolerance(faces[j])});
      if (boxes[i].IsOut(boxes[j])) continue;  // the faces are apart
      const std::optional<gp_Lin> line = contactLine(surfaces[i], surfaces[j], tol);
      if (!line || joinedAlong(faces[i], faces[j], *line, tol)) continue;
      if (boxes[i].IsOut(*line) || boxes[j].IsOut(*line)) continue;  // the line misses a face
      for (const auto& [p, q] : contactRuns(*line, faces[i], surfaces[i], faces[j], surfaces[j], boxes[j], tol,
                                            kMinRunRel * diag)) {
        // through both faces, not along a boundary of either
        const gp_Pnt mid((p.XYZ() + q.XYZ()) / 2);
        if (inFace(faces[i], surfaces[i], mid, tol) && inFace(faces[j], surfaces[j], mid, tol))
          out.push_back(BRepBuilderAPI_MakeEdge(p, q).Edge());
      }
    }
  return out;
}

/// The solid with its contact edges imprinted on the faces they lie on (general fuse of
/// the solid and the edges), when that keeps it valid, of the same volume, one solid, each
/// edge's pieces shared by four faces; none otherwise.
std::optional<TopoDS_Shape> imprinted(const TopoDS_Shape& solid, const std::vector<TopoDS_Edge>& edges,
                                      Handle(BRepTools_History)& history, std::vector<TopoDS_Shape>& contact) {
  BOPAlgo_Builder gf;
  gf.AddArgument(solid);
  for (const TopoDS_Edge& e : edges) gf.AddArgument(e);
  gf.SetRunParallel(false);
  gf.Perform();
  if (gf.HasErrors()) return std::nullopt;
  const TopTools_ListOfShape& images = gf.Modified(solid);
  if (images.Extent() != 1) return std::nullopt;
  const TopoDS_Shape out = images.First();
  if (out.ShapeType() != TopAbs_SOLID || !BRepCheck_Analyzer(out).IsValid()) return std::nullopt;
  const double before = std::abs(solidVolume(solid)), after = std::abs(solidVolume(out));
  if (std::abs(after - before) > kImprintVolumeRel * before) return std::nullopt;
  // every contact edge now lies between four faces of the solid, all along (the fuse may
  // leave a piece of no length beside a vertex it ends on, in no face)
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(out, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  const auto length = [](const TopoDS_Shape& edge) {
    TopoDS_Vertex a, b;
    TopExp::Vertices(TopoDS::Edge(edge), a, b);
    return a.IsNull() || b.IsNull() ? 0.0 : BRep_Tool::Pnt(a).Distance(BRep_Tool::Pnt(b));
  };
  for (const TopoDS_Edge& e : edges) {
    const TopTools_ListOfShape& pieces = gf.Modified(e).IsEmpty() ? imageList(e) : gf.Modified(e);
    double covered = 0;
    for (const TopoDS_Shape& piece : pieces) {
      if (!edgeFaces.Contains(piece)) continue;
      TopTools_IndexedMapOfShape distinct;
      for (const TopoDS_Shape& f : edgeFaces.FindFromKey(piece)) distinct.Add(f);
      if (distinct.Extent() != 4) return std::nullopt;
      covered += length(piece);
      contact.push_back(piece);
    }
    if (covered < (1 - kCoveredRel) * length(e)) return std::nullopt;
  }
  history = gf.History();
  return out;
}

}  // namespace

void imprintSelfContacts(CadModel::Impl& impl, PrepareReport& report) {
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(impl.shape, TopAbs_SOLID, solids);
  Bnd_Box all;
  BRepBndLib::Add(impl.shape, all);
  if (all.IsVoid()) return;
  const double diag = std::sqrt(all.SquareExtent());
  std::vector<std::optional<TopoDS_Shape>> replacement(static_cast<std::size_t>(solids.Extent()) + 1);
  std::vector<Handle(BRepTools_History)> history(replacement.size());
  std::string fixed, fins;
  for (int i = 1; i <= solids.Extent(); ++i) {
    try {
      const std::vector<TopoDS_Edge> edges = contactEdges(solids(i), diag);
      if (edges.empty()) continue;
      std::vector<TopoDS_Shape> contact;
      replacement[static_cast<std::size_t>(i)] =
          imprinted(solids(i), edges, history[static_cast<std::size_t>(i)], contact);
      if (replacement[static_cast<std::size_t>(i)])
        if (std::optional<FinRemoval> fin = withoutCuspFins(*replacement[static_cast<std::size_t>(i)], contact, diag)) {
          replacement[static_cast<std::size_t>(i)] = fin->solid;
          history[static_cast<std::size_t>(i)]->Merge(fin->history);
          fins += std::string(fins.empty() ? "" : "; ") + "solid " + std::to_string(i) + ": " + num(fin->volume) +
                  " (" + num(100 * fin->volume / std::abs(solidVolume(solids(i)))) + " % of it), about " +
                  num(fin->thickness) + " thick";
        }
    } catch (const Standard_Failure&) {
      continue;  // left as it is
    }
    if (replacement[static_cast<std::size_t>(i)])
      fixed += (fixed.empty() ? "" : ", ") + std::to_string(i) + " \"" + impl.solidName(solids(i), i) + "\"";
  }
  if (fixed.empty()) return;
  std::vector<std::vector<TopoDS_Shape>> pieces(replacement.size());
  for (std::size_t i = 0; i < replacement.size(); ++i)
    if (replacement[i]) pieces[i] = {*replacement[i]};
  replaceSolids(impl, solids, pieces, history);
  report.warnings.push_back("solid(s) " + fixed +
                            " touch themselves along a line (two of their faces tangent there): the line is made an "
                            "edge of both faces, so that the mesh meets there");
  if (!fins.empty())
    report.warnings.push_back("material too thin for any tetrahedron, a fin standing on such a line, was taken off (" +
                              fins + ")");
}

}  // namespace aniso::cad::detail
