#include "mesher/volume/ThinBoundary.h"

#include <cmath>
#include <cstdint>

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "mesher/volume/BoundaryMesh.h"
#include "mesher/volume/MeshQueries.h"
#include "mesher/model/EdgeNormals.h"

namespace aniso {

namespace {

/// The outward normals of faces f and g at the middle of edge e, dotted (nullopt when one
/// of them has no pcurve or surface there).
std::optional<double> normalsAtEdgeMiddle(const Model& model, const ModelEdge& e, int f, int g) {
  const std::optional<Vec3> nf = faceNormalAtEdgeMiddle(model, e, f), ng = faceNormalAtEdgeMiddle(model, e, g);
  if (!nf || !ng) return std::nullopt;
  return nf->dot(*ng);
}

/// Does edge e close a cusp between faces f and g (their normals opposed within `angle`)?
bool closesCusp(const Model& model, const ModelEdge& e, int f, int g, double angle = kCuspAngle) {
  if (e.degenerate) return false;
  const std::optional<double> d = normalsAtEdgeMiddle(model, e, f, g);
  return d && *d < -std::cos(angle);
}

/// The point of face f a distance `step` (about) from the middle of edge e, straight into the
/// face across the edge (its loops: the face on the left of each use in (u, v), on the right
/// for a reversed face); nullopt when e is not in f's loops or has no pcurve there.
std::optional<Vec3> intoFace(const Model& model, int edge, int f, double step) {
  const ModelFace& face = model.faces[static_cast<std::size_t>(f)];
  const ModelEdge& e = model.edges[static_cast<std::size_t>(edge)];
  if (!face.surface) return std::nullopt;
  for (const Loop& loop : face.loops)
    for (const EdgeUse& use : loop.uses) {
      if (loop.slit || use.edge != edge || use.pcurve < 0 || static_cast<std::size_t>(use.pcurve) >= e.pcurves.size()) continue;
      const PCurve& pc = e.pcurves[static_cast<std::size_t>(use.pcurve)];
      if (!pc.curve) continue;
      const Curve2dD2 c = pc.curve->d2(0.5 * (e.t0 + e.t1));
      const Vec2 along = use.reversed ? Vec2(-c.d1) : Vec2(c.d1);
      Vec2 in(-along.y(), along.x());  // left of the use
      if (face.reversed) in = -in;
      const SurfaceD1 d = face.surface->d1(c.p);
      const double speed = (d.pu * in.x() + d.pv * in.y()).norm();
      if (!(speed > 0)) continue;
      return face.surface->point(c.p + in * (step / speed));
    }
  return std::nullopt;
}

/// Do faces f and g, tangent along edge e with opposed normals, hold material between them
/// (a wedge of zero angle: the wall pinched between two battery cradles) rather than a void
/// (a rod lying on a plate)? Then g lies on the inner side of f next to the edge.
bool materialBetween(const Model& model, int edge, int f, int g) {
  // the faces must part by this fraction of the step (a cylinder of radius r tangent to a
  // plane parts from it by step² / 2r, step / 2r of the step: battery cradles, 0.005–0.01)
  constexpr double kOpening = 1e-3;
  const double step = 1e-3 * model.diagonal();
  const std::optional<Vec3> pf = intoFace(model, edge, f, step), pg = intoFace(model, edge, g, step);
  const std::optional<Vec3> n = faceNormalAtEdgeMiddle(model, model.edges[static_cast<std::size_t>(edge)], f);
  // below: g inside f, by a second-order opening (coincident faces of two parts open by none)
  return pf && pg && n && n->dot(*pg - *pf) < -kOpening * step;
}

/// Samples along an edge for its box.
constexpr int kEdgeBoxSamples = 16;

/// The boxes of the model's tangent cusp edges (two faces tangent along them, closing a cusp
/// of zero angle, kTangentCuspAngle, with material between them).
std::vector<Box3> cuspEdgeBoxes(const Model& model) {
  std::vector<Box3> out;
  for (std::size_t k = 0; k < model.edges.size(); ++k) {
    const ModelEdge& e = model.edges[k];
    if (!e.curve) continue;
    bool cusp = false;  // any two of its faces (an imprinted contact line has four)
    for (std::size_t i = 0; i < e.faces.size() && !cusp; ++i)
      for (std::size_t j = i + 1; j < e.faces.size() && !cusp; ++j)
        cusp = closesCusp(model, e, e.faces[i], e.faces[j], kTangentCuspAngle) &&
               materialBetween(model, static_cast<int>(k), e.faces[i], e.faces[j]);
    if (!cusp) continue;
    Box3 b;
    for (int i = 0; i <= kEdgeBoxSamples; ++i) b.add(e.curve->point(e.t0 + (e.t1 - e.t0) * i / kEdgeBoxSamples));
    out.push_back(b);
  }
  return out;
}

/// Box a without box c: up to six slabs of a outside c (a itself when they do not overlap).
std::vector<Box3> boxMinus(Box3 a, const Box3& c) {
  if ((a.hi.array() <= c.lo.array()).any() || (a.lo.array() >= c.hi.array()).any()) return {a};
  std::vector<Box3> out;
  for (int k = 0; k < 3; ++k) {
    if (a.lo[k] < c.lo[k]) {
      Box3 slab = a;
      slab.hi[k] = c.lo[k];
      out.push_back(slab);
      a.lo[k] = c.lo[k];
    }
    if (a.hi[k] > c.hi[k]) {
      Box3 slab = a;
      slab.lo[k] = c.hi[k];
      out.push_back(slab);
      a.hi[k] = c.hi[k];
    }
  }
  return out;  // what is left of a lies in c
}

/// The CAD faces around the solid's boundary nodes (with the outward normal of each node's
/// triangles on each), and whether two faces close a cusp (meet along an edge at an angle
/// below kCuspAngle; asked per pair, remembered): what tells a cusp from a thin wall
/// (findThinBoundary).
class FaceNeighbourhood {
 public:
  FaceNeighbourhood(const Model& model, const del3d::TetMesh& m, const SolidBoundary& b) : model_(model) {
    for (std::size_t k = 0; k < b.embeddedFrom; ++k) {
      const auto& t = b.triangles[k];
      const Vec3 n = (m.point(t[1]) - m.point(t[0])).cross(m.point(t[2]) - m.point(t[0]));
      for (const del3d::VertexId v : t) nodeFaces_.push_back({{v.index, b.triangleFace[k]}, n});
    }
    std::sort(nodeFaces_.begin(), nodeFaces_.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::size_t w = 0;  // one entry per (node, face), normals summed
    for (std::size_t r = 0; r < nodeFaces_.size(); ++r)
      if (w > 0 && nodeFaces_[w - 1].first == nodeFaces_[r].first)
        nodeFaces_[w - 1].second += nodeFaces_[r].second;
      else
        nodeFaces_[w++] = nodeFaces_[r];
    nodeFaces_.resize(w);
  }
  /// Does the face of node v that faces the triangle of face f with outward normal n (its
  /// normal there the most opposed to n) close a cusp with f?
  bool oppositeFaceCloses(std::size_t v, int f, const Vec3& n) {
    const auto lo = std::lower_bound(nodeFaces_.begin(), nodeFaces_.end(), v,
                                     [](const auto& e, std::size_t key) { return e.first.first < key; });
    int opposite = -1;
    double best = 2;
    for (auto it = lo; it != nodeFaces_.end() && it->first.first == v; ++it)
      if (const double c = n.dot(it->second.normalized()); c < best) best = c, opposite = it->first.second;
    if (opposite < 0 || opposite == f || f < 0) return false;
    const auto [it, added] = cusp_.try_emplace({std::min(f, opposite), std::max(f, opposite)}, false);
    if (added) it->second = closeACusp(f, opposite);
    return it->second;
  }

 private:
  /// Do faces f and g share an edge at whose middle their normals are opposed?
  bool closeACusp(int f, int g) const {
    if (static_cast<std::size_t>(f) >= model_.faces.size() || static_cast<std::size_t>(g) >= model_.faces.size())
      return false;
    for (const Loop& loop : model_.faces[static_cast<std::size_t>(f)].loops)
      for (const EdgeUse& use : loop.uses) {
        const ModelEdge& e = model_.edges[static_cast<std::size_t>(use.edge)];
        if (std::find(e.faces.begin(), e.faces.end(), g) != e.faces.end() && closesCusp(model_, e, f, g)) return true;
      }
    return false;
  }

  const Model& model_;
  std::vector<std::pair<std::pair<std::size_t, int>, Vec3>> nodeFaces_;  // ((node, face), normal), sorted
  std::map<std::pair<int, int>, bool> cusp_;                           // (smaller face, larger) -> closes a cusp
};

}  // namespace

std::vector<ThinSpot> findThinBoundary(const SolidTetMesh& s, const SolidBoundary& b, const Model* model) {
  const del3d::TetMesh& m = s.mesh;
  const std::size_t nb = b.embeddedFrom;  // the boundary triangles (the embedded ones follow)
  std::optional<FaceNeighbourhood> near;
  if (model) near.emplace(*model, m, b);
  // Outward (area-weighted) normals at the surface nodes, from the boundary triangles.
  std::vector<Vec3> normal(m.numVertices(), Vec3::Zero());
  for (std::size_t k = 0; k < nb; ++k) {
    const auto& t = b.triangles[k];
    const Vec3 n = (m.point(t[1]) - m.point(t[0])).cross(m.point(t[2]) - m.point(t[0]));
    for (const del3d::VertexId v : t) normal[v.index] += n;
  }
  std::vector<ThinSpot> out;
  std::vector<del3d::TetId> star;
  for (std::size_t k = 0; k < nb; ++k) {
    const auto& [a, c1, c2] = b.triangles[k];
    const volume::FaceHandle h = volume::findFace(m, a, c1, c2, star);
    if (!h.valid()) continue;  // not recovered (yet): no tet stands on it
    const Vec3 p[3] = {m.point(a), m.point(c1), m.point(c2)};
    const Vec3 n = (p[1] - p[0]).cross(p[2] - p[0]).normalized();
    // the apex of the tet on the inner side (the other one, if any, is outside the solid)
    del3d::VertexId x = m.vertex(h.tet, h.face);
    if (n.dot(m.point(x) - p[0]) > 0) {
      const del3d::TetId o = m.neighbour(h.tet, h.face);
      if (!o.valid()) continue;
      for (int i = 0; i < 4; ++i)
        if (const del3d::VertexId v = m.vertex(o, i); v != a && v != c1 && v != c2) x = v;
    }
    if (!s.isFixed(x) || !(normal[x.index].norm() > 0)) continue;
    if (n.dot(normal[x.index].normalized()) > kOppositeNormalCos) continue;
    if (near && near->oppositeFaceCloses(x.index, b.triangleFace[k], n)) continue;  // a cusp
    const Vec3 centroid = (p[0] + p[1] + p[2]) / 3;
    const double height = -n.dot(m.point(x) - centroid);
    const double size = ((p[1] - p[0]).norm() + (p[2] - p[1]).norm() + (p[0] - p[2]).norm()) / 3;
    if (!(height > 0) || height >= kThinRatio * size) continue;
    out.push_back({b.triangleFace[k], centroid, size, height});
  }
  if (static_cast<double>(out.size()) < kThinFraction * static_cast<double>(nb)) out.clear();
  return out;
}

std::vector<SizingSource> thinSources(const std::vector<ThinSpot>& spots, double hmin,
                                      std::vector<std::pair<int, double>>* faces, const Model* model) {
  struct Acc {
    Box3 box;
    double grow = 0;
    std::vector<double> targets;
    std::set<int> solids;
  };
  std::map<int, Acc> byFace;
  for (const ThinSpot& s : spots) {
    const double target = std::max(s.thickness, hmin);
    if (target >= kThinRatio * s.size) continue;  // as fine as hmin allows already
    Acc& a = byFace[s.face];
    a.box.add(s.centroid);
    a.grow = std::max(a.grow, s.size);
    a.targets.push_back(target);
    if (s.solid >= 0) a.solids.insert(s.solid);
  }
  std::map<int, std::vector<int>> solidFaces;  // each thin solid's faces, computed once
  if (model)
    for (const auto& [face, a] : byFace)
      for (const int s : a.solids)
        if (!solidFaces.count(s)) solidFaces[s] = model->solidBoundaryFaces(s);
  // the sources stay clear of cusp edges (ThinBoundary.h)
  const std::vector<Box3> cusps = model ? cuspEdgeBoxes(*model) : std::vector<Box3>();
  std::vector<SizingSource> out;
  for (auto& [face, a] : byFace) {
    // the face's thickness: a low quantile of its spots', not the smallest
    const auto q = a.targets.begin() + static_cast<std::ptrdiff_t>(kFaceThicknessQuantile * (a.targets.size() - 1));
    std::nth_element(a.targets.begin(), q, a.targets.end());
    SizingSource src;
    src.kind = SizingSource::Kind::Box;
    src.a = a.box.lo - Vec3::Constant(a.grow);
    src.b = a.box.hi + Vec3::Constant(a.grow);
    src.metric = Metric3d::isotropic(*q);
    if (model && !a.solids.empty()) {
      for (const int s : a.solids) src.faces.insert(src.faces.end(), solidFaces[s].begin(), solidFaces[s].end());
      if (a.solids.size() > 1) {  // a face of two thin solids
        std::sort(src.faces.begin(), src.faces.end());
        src.faces.erase(std::unique(src.faces.begin(), src.faces.end()), src.faces.end());
      }
    }
    std::vector<Box3> pieces = {Box3{src.a, src.b}};
    for (const Box3& c : cusps) {
      Box3 clear = c;
      clear.lo -= Vec3::Constant(kCuspClearance * *q);
      clear.hi += Vec3::Constant(kCuspClearance * *q);
      std::vector<Box3> next;
      for (const Box3& p : pieces)
        for (const Box3& r : boxMinus(p, clear)) next.push_back(r);
      pieces.swap(next);
    }
    for (const Box3& p : pieces) {
      src.a = p.lo;
      src.b = p.hi;
      out.push_back(src);
      if (faces) faces->push_back({face, *q});
    }
  }
  return out;
}

namespace {

/// The triangles' centroids in a uniform grid (about two per cell, at most kMaxCells cells),
/// for the sources' region queries: a source then tests the triangles of the cells its box
/// meets instead of every triangle of its faces.
class CentroidGrid {
 public:
  static constexpr std::size_t kMaxCells = std::size_t{1} << 21;

  explicit CentroidGrid(const std::vector<Vec3>& centroid) {
    for (const Vec3& c : centroid) box_.add(c);
    if (centroid.empty()) return;
    const Vec3 size = box_.size().cwiseMax(1e-12 * std::max(1.0, box_.diagonal()));
    const double cells = std::clamp(static_cast<double>(centroid.size()) / 2, 1.0, static_cast<double>(kMaxCells));
    const double cell = std::cbrt(size.prod() / cells);
    for (int k = 0; k < 3; ++k) n_[k] = std::clamp(static_cast<int>(std::ceil(size[k] / cell)), 1, 1 << 10);
    while (static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] > kMaxCells)
      for (int k = 0; k < 3; ++k) n_[k] = std::max(1, n_[k] / 2);
    for (int k = 0; k < 3; ++k) scale_[k] = n_[k] / size[k];
    const std::size_t nc = static_cast<std::size_t>(n_[0]) * n_[1] * n_[2];
    std::vector<std::size_t> cellOf(centroid.size());
    start_.assign(nc + 1, 0);
    for (std::size_t i = 0; i < centroid.size(); ++i) ++start_[(cellOf[i] = cellIndex(centroid[i])) + 1];
    for (std::size_t c = 0; c < nc; ++c) start_[c + 1] += start_[c];
    items_.resize(centroid.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < centroid.size(); ++i) items_[fill[cellOf[i]]++] = static_cast<std::uint32_t>(i);
  }

  /// Would visit() pass fewer than `limit` triangles for this box, counting its cells as
  /// work too? (Stops counting at the limit.)
  bool cheaperThan(const Box3& b, std::size_t limit) const {
    int a[3], z[3];
    if (!range(b, a, z)) return true;
    std::size_t cells = 1;
    for (int k = 0; k < 3; ++k) cells *= static_cast<std::size_t>(z[k] - a[k] + 1);
    if (cells >= limit) return false;
    std::size_t n = cells;
    for (int iz = a[2]; iz <= z[2] && n < limit; ++iz)
      for (int iy = a[1]; iy <= z[1] && n < limit; ++iy)
        for (int ix = a[0]; ix <= z[0]; ++ix) {
          const std::size_t c = (static_cast<std::size_t>(iz) * n_[1] + iy) * n_[0] + ix;
          n += start_[c + 1] - start_[c];
        }
    return n < limit;
  }
  /// f(i) for every triangle whose centroid lies in a cell the box meets.
  template <class F>
  void visit(const Box3& b, F f) const {
    int a[3], z[3];
    if (!range(b, a, z)) return;
    for (int iz = a[2]; iz <= z[2]; ++iz)
      for (int iy = a[1]; iy <= z[1]; ++iy)
        for (int ix = a[0]; ix <= z[0]; ++ix) {
          const std::size_t c = (static_cast<std::size_t>(iz) * n_[1] + iy) * n_[0] + ix;
          for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) f(items_[k]);
        }
  }

 private:
  int coord(const Vec3& p, int k) const {
    return std::clamp(static_cast<int>(std::floor((p[k] - box_.lo[k]) * scale_[k])), 0, n_[k] - 1);
  }
  std::size_t cellIndex(const Vec3& p) const {
    return (static_cast<std::size_t>(coord(p, 2)) * n_[1] + coord(p, 1)) * n_[0] + coord(p, 0);
  }
  /// The cell range of the query box; false when it meets no cell.
  bool range(const Box3& query, int a[3], int z[3]) const {
    if (items_.empty() || query.empty()) return false;
    // a margin for the rounding of the region's box (SizingSource::bounds)
    const Vec3 margin = Vec3::Constant(1e-9 * (query.diagonal() + box_.diagonal()));
    const Vec3 lo = query.lo - margin, hi = query.hi + margin;
    if ((hi.array() < box_.lo.array()).any() || (lo.array() > box_.hi.array()).any()) return false;
    for (int k = 0; k < 3; ++k) a[k] = coord(lo, k), z[k] = coord(hi, k);
    return true;
  }

  Box3 box_;
  int n_[3] = {1, 1, 1};
  Vec3 scale_ = Vec3::Ones();
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> items_;
};

}  // namespace

double predictedTriangles(const SurfaceMesh& surface, const std::vector<SizingSource>& sources) {
  // Each source visits the triangles of its faces, or those of the grid cells its region's
  // box meets when fewer (all triangles' cells when it has no faces), its size taken once:
  // the budget's bisection calls this a dozen times with hundreds of sources on a surface
  // of millions of triangles. Every triangle's target is the smallest size of the sources
  // containing its centroid (in any order), then the same sum in triangle order.
  const std::size_t nt = surface.triangles.size();
  const auto faceOf = [&](std::size_t i) { return i < surface.triangleFace.size() ? surface.triangleFace[i] : -1; };
  int nf = 0;
  for (std::size_t i = 0; i < nt; ++i) nf = std::max(nf, faceOf(i) + 1);
  const std::vector<std::vector<int>> byFace = trianglesByFace(surface, nf);
  std::vector<Vec3> centroid(nt);
  for (std::size_t i = 0; i < nt; ++i) {
    const auto& t = surface.triangles[i];
    centroid[i] = (surface.nodes[t[0]] + surface.nodes[t[1]] + surface.nodes[t[2]]) / 3;
  }
  const CentroidGrid grid(centroid);
  std::vector<int> faceMark(static_cast<std::size_t>(nf), -1);  // the source (index) sizing face f
  std::vector<double> target(nt, 1e300);
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const SizingSource& src = sources[s];
    const double h = src.metric.axes().lengths.minCoeff();
    const auto visit = [&](std::size_t i) {
      if (src.contains(centroid[i])) target[i] = std::min(target[i], h);
    };
    const Box3 region = src.bounds();
    if (src.faces.empty()) {
      grid.visit(region, visit);
      continue;
    }
    std::size_t onFaces = 0;
    for (const int f : src.faces)
      if (f >= 0 && f < nf) onFaces += byFace[static_cast<std::size_t>(f)].size(), faceMark[f] = static_cast<int>(s);
    if (grid.cheaperThan(region, onFaces)) {
      grid.visit(region, [&](std::size_t i) {
        const int f = faceOf(i);
        if (f >= 0 && faceMark[static_cast<std::size_t>(f)] == static_cast<int>(s)) visit(i);
      });
      continue;
    }
    for (const int f : src.faces)
      if (f >= 0 && f < nf)
        for (const int i : byFace[static_cast<std::size_t>(f)]) visit(static_cast<std::size_t>(i));
  }
  double n = 0;
  for (std::size_t i = 0; i < nt; ++i) {
    const auto& t = surface.triangles[i];
    const Vec3 p[3] = {surface.nodes[t[0]], surface.nodes[t[1]], surface.nodes[t[2]]};
    const double size = ((p[1] - p[0]).norm() + (p[2] - p[1]).norm() + (p[0] - p[2]).norm()) / 3;
    n += std::max(1.0, (size / target[i]) * (size / target[i]));
  }
  return n;
}

std::vector<SizingSource> sourcesWithinBudget(const SurfaceMesh& surface, const std::vector<SizingSource>& sources,
                                              double budget, double* factor, double maxFactor) {
  auto scaled = [&](double s) {
    std::vector<SizingSource> out = sources;
    for (SizingSource& src : out) src.metric = Metric3d::isotropic(s * src.metric.axes().lengths.minCoeff());
    return out;
  };
  if (factor) *factor = 1.0;
  if (predictedTriangles(surface, sources) <= budget) return sources;
  // predictedTriangles decreases with s; at the largest source's coarsest triangle no
  // triangle is refined any more (every term 1), so the bisection has a bracket as long
  // as the budget holds the mesh itself.
  if (predictedTriangles(surface, scaled(maxFactor)) > budget) {
    if (factor) *factor = maxFactor;
    return scaled(maxFactor);
  }
  double lo = 1.0, hi = std::min(2.0, maxFactor);
  while (predictedTriangles(surface, scaled(hi)) > budget) lo = hi, hi = std::min(2 * hi, maxFactor);
  while (hi / lo > 1.01) {
    const double mid = std::sqrt(lo * hi);
    (predictedTriangles(surface, scaled(mid)) > budget ? lo : hi) = mid;
  }
  if (factor) *factor = hi;
  return scaled(hi);
}

std::vector<std::size_t> cheapestGroupsWithinBudget(const SurfaceMesh& surface,
                                                    const std::vector<SizingSource>& sources, double budget,
                                                    std::size_t* groups, std::size_t* kept) {
  std::map<std::vector<int>, std::vector<std::size_t>> byFaces;  // group -> its sources
  std::vector<const std::vector<std::size_t>*> order;            // groups by first source
  for (std::size_t i = 0; i < sources.size(); ++i) {
    auto [it, added] = byFaces.try_emplace(sources[i].faces);
    it->second.push_back(i);
    if (added) order.push_back(&it->second);
  }
  const double triangles = static_cast<double>(surface.triangles.size());
  std::vector<std::pair<double, std::size_t>> growth;  // (growth, group in `order`)
  for (std::size_t g = 0; g < order.size(); ++g) {
    std::vector<SizingSource> alone;
    for (const std::size_t i : *order[g]) alone.push_back(sources[i]);
    growth.push_back({predictedTriangles(surface, alone) - triangles, g});
  }
  std::stable_sort(growth.begin(), growth.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<std::size_t> out;
  double total = triangles;
  std::size_t taken = 0;
  for (const auto& [grow, g] : growth) {
    if (total + grow > budget) break;  // the rest grow as much or more
    total += grow;
    ++taken;
    out.insert(out.end(), order[g]->begin(), order[g]->end());
  }
  std::sort(out.begin(), out.end());
  if (groups) *groups = order.size();
  if (kept) *kept = taken;
  return out;
}

}  // namespace aniso
