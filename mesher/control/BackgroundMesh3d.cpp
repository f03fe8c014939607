// BackgroundMesh3d: construction, point location, interpolation (sec. 3.4.5), vertex
// insertion, vertex-wide operations, export and validation. The adaptation procedures
// are in BackgroundMesh3dAdapt.cpp.
#include "mesher/control/BackgroundMesh3d.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <sstream>

#include "mesher/core/Error.h"
#include "mesher/delaunay3d/EdgeRing.h"
#include "mesher/delaunay3d/EnclosingBox.h"
#include "mesher/delaunay3d/Validate.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/metric/SymmetricEigen.h"
#include "mesher/predicates/Predicates.h"

namespace aniso {

using del3d::TetId;
using del3d::VertexId;

namespace {

std::string pointText(const Vec3& x) {
  std::ostringstream s;
  s.precision(10);
  s << "(" << x.x() << ", " << x.y() << ", " << x.z() << ")";
  return s.str();
}

/// A query within this many edge lengths of the hint's first vertex starts its walk at
/// the hint; farther ones at the seed octree.
constexpr double kHintReach = 2.0;
/// Vertices per seed-octree leaf (all compared per query: the nearest leaves a walk of a
/// step or two).
constexpr std::uint32_t kSeedLeaf = 8;

const Box3& checkedBounds(const Box3& b) {
  if (b.empty() || !b.lo.allFinite() || !b.hi.allFinite())
    throw InputError("background mesh control space: the bounds are empty or not finite");
  return b;
}

}  // namespace

BackgroundMesh3d::BackgroundMesh3d(const Box3& bounds, const SizingParameters& params,
                                   const BackgroundMeshOptions& options)
    : bounds_(checkedBounds(bounds)),
      epsM_(params.metricDistanceEps),
      epsDelta_(params.metricDifferenceEps),
      lMax_(params.adaptLengthMax),
      options_(options),
      mesh_(std::make_unique<del3d::TetMesh>()) {
  checkBackgroundParameters(params, options);
  const del3d::EnclosingBox box = del3d::createEnclosingBox(*mesh_, bounds_, options.boxMargin);
  inserter_ = std::make_unique<del3d::Inserter>(*mesh_);
  seeds_ = std::make_unique<VertexSeedOctree>(box.box, kSeedLeaf);
  for (std::uint32_t v = 0; v < mesh_->numVertices(); ++v) seeds_->insert(v, mesh_->point(VertexId(v)));
  const std::size_t nv = mesh_->numVertices();
  metric_.resize(nv);
  length_.assign(nv, Mat3::Identity());
  known_.assign(nv, 0);
}

void BackgroundMesh3d::setInterpolation(BackgroundInterpolation method) {
  options_.interpolation = method;
  ++revision_;
}

void BackgroundMesh3d::failFresh(const Vec3& x) const {
  throw MeshingError("background mesh control space: metric requested at " + pointText(x) +
                     " before the control vertices carry a metric (set a continuous source or call "
                     "initializeControlVertices)");
}

// ---- point location ----

TetId BackgroundMesh3d::locateFrom(const Vec3& p, TetId start, std::uint32_t& rng) const {
  if (!start.valid() || !mesh_->isAlive(start)) start = mesh_->vertexTet(VertexId(seeds_->nearest(p)));
  for (std::uint32_t k = 0; !start.valid() && k < mesh_->tetSlots(); ++k)
    if (mesh_->isAlive(TetId(k))) start = TetId(k);
  const del3d::LocateResult r = del3d::locate(*mesh_, p.data(), start, rng);
  if (r.status == del3d::LocateStatus::Outside || !r.tet.valid())
    throw MeshingError("background mesh control space: point location failed at " + pointText(p));
  // On a face or an edge several tetrahedra contain p: take the one with the smallest
  // slot, so that the field (A_t, A_s) does not depend on where the walk came from. On a
  // vertex every set holds the vertex and the ε_M shortcut answers.
  TetId t = r.tet;
  if (r.status == del3d::LocateStatus::OnFace) {
    const TetId u = mesh_->neighbour(t, std::countr_zero(r.zeroFaces));
    if (u.valid() && u.index < t.index) t = u;
  } else if (r.status == del3d::LocateStatus::OnEdge) {
    int ends[2], n = 0;
    for (int i = 0; i < 4; ++i)
      if (!((r.zeroFaces >> i) & 1u)) ends[n++] = i;
    std::array<TetId, 64> ring;
    std::array<VertexId, 64> apex;
    const int m = del3d::closedEdgeRing(*mesh_, r.tet, ends[0], ends[1], ring, apex);
    for (int k = 0; k < m; ++k)
      if (ring[k].index < t.index) t = ring[k];
  }
  return t;
}

TetId BackgroundMesh3d::locate(const Vec3& x, MeshLocateHint3d& hint) const {
  const Vec3 p = clamp(x);
  TetId start(hint.tet);
  if (start.valid() && mesh_->isAlive(start)) {
    const std::uint32_t* tv = mesh_->tetVertices(start);
    const Vec3 a = mesh_->point(VertexId(tv[0]));
    double edge = 0;
    for (int i = 1; i < 4; ++i) edge = std::max(edge, (mesh_->point(VertexId(tv[i])) - a).squaredNorm());
    if ((p - a).squaredNorm() > kHintReach * kHintReach * edge) start = TetId();
  } else {
    start = TetId();
  }
  const TetId t = locateFrom(p, start, hint.rng);
  hint.tet = t.index;
  return t;
}

// ---- interpolation ----

int BackgroundMesh3d::gather(const Vec3& p, TetId t, BackgroundInterpolation method, std::uint32_t* out) const {
  const std::uint32_t* tv = mesh_->tetVertices(t);
  if (method == BackgroundInterpolation::Single) {
    int best = 0;
    double bestD = 0;
    for (int i = 0; i < 4; ++i) {
      const double d = (p - mesh_->point(VertexId(tv[i]))).squaredNorm();
      if (i == 0 || d < bestD) {
        best = i;
        bestD = d;
      }
    }
    out[0] = tv[best];
    return 1;
  }
  if (method == BackgroundInterpolation::Element) {
    for (int i = 0; i < 4; ++i) out[i] = tv[i];
    return 4;
  }
  // A_o: breadth-first search through the tetrahedra whose circumsphere strictly contains
  // p (connected, see BackgroundMesh2d::gather).
  std::array<std::uint32_t, kMaxNeighbourhood> in;
  std::array<std::uint32_t, 4 * kMaxNeighbourhood> seen;
  int nIn = 0, nSeen = 0;
  in[nIn++] = t.index;
  seen[nSeen++] = t.index;
  for (int k = 0; k < nIn; ++k) {
    for (int i = 0; i < 4; ++i) {
      const TetId u = mesh_->neighbour(TetId(in[k]), i);
      if (!u.valid() || std::find(seen.begin(), seen.begin() + nSeen, u.index) != seen.begin() + nSeen) continue;
      if (nSeen == static_cast<int>(seen.size()) || nIn == kMaxNeighbourhood) continue;
      seen[nSeen++] = u.index;
      const std::uint32_t* uv = mesh_->tetVertices(u);
      if (predicates::insphere(mesh_->coords(VertexId(uv[0])), mesh_->coords(VertexId(uv[1])),
                               mesh_->coords(VertexId(uv[2])), mesh_->coords(VertexId(uv[3])), p.data()) > 0)
        in[nIn++] = u.index;
    }
  }
  int n = 0;
  for (int k = 0; k < nIn; ++k) {
    const std::uint32_t* uv = mesh_->tetVertices(TetId(in[k]));
    for (int i = 0; i < 4; ++i)
      if (std::find(out, out + n, uv[i]) == out + n) out[n++] = uv[i];
  }
  return n;
}

Metric3d BackgroundMesh3d::blendMetric(const Vec3& p, const std::uint32_t* set, int n) const {
  if (n == 1) return metric_[set[0]];
  double w[kMaxNeighbourhood + 3];
  int best = -1;
  double bestD = epsM_;
  for (int i = 0; i < n; ++i) {
    const Vec3 d = p - mesh_->point(VertexId(set[i]));
    const double r2 = d.squaredNorm();
    if (r2 == 0) return metric_[set[i]];
    const double dM = (metric_[set[i]].matrix() * d).norm();
    if (dM < bestD) {
      bestD = dM;
      best = i;
    }
    w[i] = 1 / r2;
  }
  if (best >= 0) return metric_[set[best]];  // ε_M shortcut
  Mat3 l = Mat3::Zero();
  double total = 0;
  for (int i = 0; i < n; ++i) {
    l += w[i] * length_[set[i]];
    total += w[i];
  }
  return Metric3d::fromTransformation(symmetrize<3>(Mat3((l / total).inverse())));
}

Metric3d BackgroundMesh3d::fieldNear(const Vec3& p, TetId near) const {
  std::uint32_t rng = 0x2545F491u;
  const TetId t = locateFrom(p, near, rng);
  std::uint32_t set[kMaxNeighbourhood + 3];
  return blendMetric(p, set, gather(p, t, options_.interpolation, set));
}

Metric3d BackgroundMesh3d::metricAt(const Vec3& x, MeshLocateHint3d& hint) const {
  if (!valued_) failFresh(x);
  const Vec3 p = clamp(x);
  const TetId t = locate(p, hint);
  std::uint32_t set[kMaxNeighbourhood + 3];
  return blendMetric(p, set, gather(p, t, options_.interpolation, set));
}

int BackgroundMesh3d::interpolationSet(const Vec3& x, MeshLocateHint3d& hint, BackgroundInterpolation method,
                                       std::vector<int>& out) const {
  const Vec3 p = clamp(x);
  const TetId t = locate(p, hint);
  std::uint32_t set[kMaxNeighbourhood + 3];
  const int n = gather(p, t, method, set);
  out.assign(set, set + n);
  return n;
}

// ---- structure ----

BackgroundMesh3d::Inserted BackgroundMesh3d::insertVertex(const Vec3& p, const Metric3d& m, bool known, TetId near) {
  const del3d::InsertResult r = inserter_->insert(p, near.valid() && mesh_->isAlive(near) ? near : TetId());
  Inserted res;
  if (r.status == del3d::InsertStatus::Duplicate) {
    res.vertex = static_cast<int>(r.vertex.index);
  } else if (r.status == del3d::InsertStatus::Inserted) {
    res.vertex = static_cast<int>(r.vertex.index);
    res.created = true;
    seeds_->insert(r.vertex.index, p);
    const std::size_t nv = mesh_->numVertices();
    metric_.resize(nv);
    length_.resize(nv, Mat3::Identity());
    known_.resize(nv, 0);
    metric_[res.vertex] = m;
    length_[res.vertex] = m.inverseMatrix();
    known_[res.vertex] = known ? 1 : 0;
  }
  return res;
}

void BackgroundMesh3d::appendStar(int v, std::vector<TetId>& out) const {
  const VertexId vid(static_cast<std::uint32_t>(v));
  const TetId first = mesh_->vertexTet(vid);
  if (!first.valid()) return;
  const std::size_t begin = out.size();
  out.push_back(first);
  for (std::size_t k = begin; k < out.size(); ++k) {
    const TetId t = out[k];
    const int own = mesh_->localIndex(t, vid);
    for (int j = 0; j < 4; ++j) {
      if (j == own) continue;  // the faces through v are those opposite its other vertices
      const TetId u = mesh_->neighbour(t, j);
      if (u.valid() && std::find(out.begin() + static_cast<std::ptrdiff_t>(begin), out.end(), u) == out.end())
        out.push_back(u);
    }
  }
}

void BackgroundMesh3d::neighbours(int v, std::vector<int>& out) const {
  std::vector<TetId> star;
  appendStar(v, star);
  out.clear();
  for (TetId t : star)
    for (int i = 0; i < 4; ++i) {
      const int w = static_cast<int>(mesh_->vertex(t, i).index);
      if (w != v && std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
    }
}

Vec3 BackgroundMesh3d::centroid(TetId t) const {
  const std::uint32_t* tv = mesh_->tetVertices(t);
  Vec3 c = Vec3::Zero();
  for (int i = 0; i < 4; ++i) c += mesh_->point(VertexId(tv[i]));
  return c / 4;
}

void BackgroundMesh3d::setVertex(int v, const Metric3d& m) {
  metric_[v] = m;
  length_[v] = m.inverseMatrix();
}

void BackgroundMesh3d::intersectVertex(int v, const Metric3d& m) {
  if (intersectInto(metric_[v], m)) length_[v] = metric_[v].inverseMatrix();
}

VertexGraph BackgroundMesh3d::graph() const {
  static constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  std::vector<std::array<int, 2>> pairs;
  pairs.reserve(6 * mesh_->numTets());
  for (std::uint32_t k = 0; k < mesh_->tetSlots(); ++k) {
    if (!mesh_->isAlive(TetId(k))) continue;
    const std::uint32_t* tv = mesh_->tetVertices(TetId(k));
    for (const auto& e : kEdge) pairs.push_back({static_cast<int>(tv[e[0]]), static_cast<int>(tv[e[1]])});
  }
  return makeVertexGraph(vertexCount(), std::move(pairs));
}

int BackgroundMesh3d::smoothGradation(double gamma) {
  if (!valued_) failFresh(bounds_.lo);
  const Modification done{*this};
  const VertexGraph g = graph();
  std::vector<Vec3> d(g.edges.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) d[e] = point(g.edges[e][1]) - point(g.edges[e][0]);
  std::vector<std::uint8_t> changed(metric_.size(), 0);
  const int rounds = smoothByEdgeMarking<3>(g, d, gamma, metric_, changed);
  for (std::size_t v = 0; v < metric_.size(); ++v)
    if (changed[v]) length_[v] = metric_[v].inverseMatrix();
  return rounds;
}

void BackgroundMesh3d::forEachVertex(const VertexVisitor& visit) const {
  if (!valued_) return;
  for (int v = 0; v < vertexCount(); ++v) visit(point(v), metric_[v]);
}

void BackgroundMesh3d::modifyVertices(const VertexModifier& modify) {
  if (!valued_) return;
  const Modification done{*this};
  for (int v = 0; v < vertexCount(); ++v) {
    Metric3d m = metric_[v];
    if (modify(point(v), m)) setVertex(v, m);
  }
}

ControlSpaceGrid BackgroundMesh3d::grid() const {
  ControlSpaceGrid g;
  g.dim = 3;
  g.cellSize = 4;
  const int nv = vertexCount();
  g.points.resize(nv);
  for (int v = 0; v < nv; ++v) g.points[v] = point(v);
  for (std::uint32_t k = 0; k < mesh_->tetSlots(); ++k) {
    if (!mesh_->isAlive(TetId(k))) continue;
    const std::uint32_t* tv = mesh_->tetVertices(TetId(k));
    for (int i = 0; i < 4; ++i) g.cells.push_back(static_cast<int>(tv[i]));  // orient3d > 0: VTK order
    g.cellLevel.push_back(0);
  }
  if (valued_) {
    g.metric.resize(nv);
    g.lengths.resize(nv);
    g.directions.resize(nv);
    for (int v = 0; v < nv; ++v) {
      const MetricAxes<3> a = metric_[v].axes();
      g.metric[v] = metric_[v].matrix();
      g.lengths[v] = a.lengths;
      g.directions[v] = a.directions;
    }
  }
  return g;
}

void BackgroundMesh3d::validate() const {
  const std::string where = "background mesh control space invalid: ";
  del3d::ValidateOptions vo;
  vo.checkDelaunay = true;
  const std::vector<std::string> problems = del3d::validate(*mesh_, vo);
  if (!problems.empty()) throw MeshingError(where + problems.front());
  const std::size_t nv = mesh_->numVertices();
  if (metric_.size() != nv || length_.size() != nv || known_.size() != nv)
    throw MeshingError(where + "per-vertex arrays do not match the vertex count");
  std::size_t known = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    known += known_[v];
    if (valued_ && !known_[v]) throw MeshingError(where + "vertex " + std::to_string(v) + " carries no metric");
    if (!mesh_->vertexTet(VertexId(static_cast<std::uint32_t>(v))).valid())
      throw MeshingError(where + "vertex " + std::to_string(v) + " is in no tetrahedron");
    if (!known_[v]) continue;
    const Mat3& m = metric_[v].matrix();
    if (!isSymmetricPositiveDefinite(m))
      throw MeshingError(where + "metric of vertex " + std::to_string(v) + " is not SPD");
    if (!((length_[v] * m - Mat3::Identity()).norm() < 1e-8))
      throw MeshingError(where + "stored inverse of vertex " + std::to_string(v) + " is stale");
  }
  if (!valued_ && known != pending_)
    throw MeshingError(where + "pending point sources (" + std::to_string(pending_) + ") do not match the " +
                       std::to_string(known) + " vertices carrying a metric");
}

}  // namespace aniso
