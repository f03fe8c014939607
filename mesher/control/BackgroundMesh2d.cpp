// BackgroundMesh2d: construction, point location, interpolation (sec. 3.4.5), vertex
// insertion, vertex-wide operations, export and validation. The adaptation procedures
// (3.4.1–3.4.3) are in BackgroundMesh2dAdapt.cpp.
#include "mesher/control/BackgroundMesh2d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "mesher/core/Error.h"
#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/PointLocation.h"
#include "mesher/delaunay/Validate2d.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/metric/SymmetricEigen.h"
#include "mesher/predicates/Predicates.h"

namespace aniso {

using del2d::kNext;
using del2d::kPrev;
using del2d::TriId;
using del2d::VertexId;

namespace {

std::string pointText(const Vec2& x) {
  std::ostringstream s;
  s.precision(10);
  s << "(" << x.x() << ", " << x.y() << ")";
  return s.str();
}

/// A query within this many edge lengths of the hint's first vertex starts its walk at
/// the hint; farther ones at the seeding quadtree.
constexpr double kHintReach = 2.0;
/// Seeding quadtree leaves of at most this many vertices, all compared per query (the
/// thesis' 300 suits a mesh queried about once per insertion; a control space is queried
/// far more often than it changes, and the nearest vertex leaves a walk of 1–2 steps).
constexpr std::uint32_t kSeedLeaf = 8;

inline std::uint32_t nextRandom(std::uint32_t& s) {
  if (s == 0) s = 0x9E3779B9u;
  s ^= s << 13;
  s ^= s >> 17;
  s ^= s << 5;
  return s;
}

del2d::Triangulation2dOptions kernelOptions(const BackgroundMeshOptions& o) {
  del2d::Triangulation2dOptions t;
  t.boxMargin = o.boxMargin;
  t.quadtree.leafThreshold = kSeedLeaf;
  t.quadtree.sampleSize = kSeedLeaf;
  return t;
}

const Box2& checkedBounds(const Box2& b) {
  if (b.empty() || !b.lo.allFinite() || !b.hi.allFinite())
    throw InputError("background mesh control space: the bounds are empty or not finite");
  return b;
}

}  // namespace

void checkBackgroundParameters(const SizingParameters& params, const BackgroundMeshOptions& o) {
  if (!(std::isfinite(params.metricDistanceEps) && params.metricDistanceEps >= 0))
    throw InputError("control space: metric distance threshold epsilon_M must be finite and >= 0");
  if (!(std::isfinite(params.metricDifferenceEps) && params.metricDifferenceEps > 0))
    throw InputError("control space: metric difference threshold epsilon_delta must be finite and > 0");
  if (!(std::isfinite(params.adaptLengthMax) && params.adaptLengthMax > 0))
    throw InputError("control space: adaptation length threshold l_Mmax must be finite and > 0");
  if (o.initialGrid < 2) throw InputError("background mesh: initialGrid must be >= 2");
  if (!(std::isfinite(o.minElementMetricLength) && o.minElementMetricLength >= 0))
    throw InputError("background mesh: minElementMetricLength must be finite and >= 0");
  if (o.maxVertices < 16) throw InputError("background mesh: maxVertices must be >= 16");
  if (o.maxRingRounds < 0) throw InputError("background mesh: maxRingRounds must be >= 0");
  if (!(std::isfinite(o.boxMargin) && o.boxMargin > 0)) throw InputError("background mesh: boxMargin must be > 0");
}

BackgroundMesh2d::BackgroundMesh2d(const Box2& bounds, const SizingParameters& params,
                                   const BackgroundMeshOptions& options)
    : bounds_(checkedBounds(bounds)),
      epsM_(params.metricDistanceEps),
      epsDelta_(params.metricDifferenceEps),
      lMax_(params.adaptLengthMax),
      options_(options),
      tri_((checkBackgroundParameters(params, options), bounds), kernelOptions(options)) {
  const std::size_t nv = tri_.numVertices();
  metric_.resize(nv);
  length_.assign(nv, Mat2::Identity());
  aux_.assign(nv, Mat2::Identity());
  known_.assign(nv, 0);
  tri_.seeds();
}

void BackgroundMesh2d::setInterpolation(BackgroundInterpolation method) {
  options_.interpolation = method;
  ++revision_;
}

void BackgroundMesh2d::failFresh(const Vec2& x) const {
  throw MeshingError("background mesh control space: metric requested at " + pointText(x) +
                     " before the control vertices carry a metric (set a continuous source or call "
                     "initializeControlVertices)");
}

// ---- point location ----

TriId BackgroundMesh2d::walk(const Vec2& p, TriId t, std::uint32_t& rng, unsigned& zeros) const {
  // Remembering stochastic visibility walk (as PointLocation.cpp) on the caller's random
  // state; exact orient2d. The edge just crossed has p strictly inside, so its skipped
  // test never hides a zero.
  const double* pp = p.data();
  const std::size_t limit = std::max<std::size_t>(1000, 2 * tri_.numTriangles());
  TriId from;
  for (std::size_t steps = 0; steps < limit; ++steps) {
    const std::uint32_t* tv = tri_.triVertices(t);
    const std::uint32_t* tn = tri_.triNeighbours(t);
    const int r = static_cast<int>(nextRandom(rng) % 3u);
    TriId next;
    bool outside = false;
    zeros = 0;
    for (int k = 0; k < 3; ++k) {
      const int i = r + k < 3 ? r + k : r + k - 3;
      const TriId u(tn[i]);
      if (from.valid() && u == from) continue;
      const double o =
          predicates::orient2d(tri_.coords(VertexId(tv[kNext[i]])), tri_.coords(VertexId(tv[kPrev[i]])), pp);
      if (o == 0) zeros |= 1u << i;
      if (o < 0) {
        if (!u.valid()) {
          outside = true;
          continue;
        }
        next = u;
        break;
      }
    }
    if (next.valid()) {
      from = t;
      t = next;
      continue;
    }
    return outside ? TriId() : t;
  }
  for (std::uint32_t k = 0; k < tri_.triangleSlots(); ++k) {
    const TriId s(k);
    if (!tri_.isAlive(s)) continue;
    const std::uint32_t* tv = tri_.triVertices(s);
    bool inside = true;
    zeros = 0;
    for (int i = 0; i < 3 && inside; ++i) {
      const double o =
          predicates::orient2d(tri_.coords(VertexId(tv[kNext[i]])), tri_.coords(VertexId(tv[kPrev[i]])), pp);
      inside = o >= 0;
      if (o == 0) zeros |= 1u << i;
    }
    if (inside) return s;
  }
  return TriId();
}

TriId BackgroundMesh2d::locateFrom(const Vec2& p, TriId start, std::uint32_t& rng) const {
  if (!start.valid() || !tri_.isAlive(start)) start = del2d::seedTriangle(tri_, p);
  unsigned zeros = 0;
  TriId t = start.valid() ? walk(p, start, rng, zeros) : TriId();
  if (!t.valid()) throw MeshingError("background mesh control space: point location failed at " + pointText(p));
  // On an edge both triangles contain p: take the one with the smaller slot, so that the
  // field (A_t, A_s) does not depend on where the walk came from. On a vertex every set
  // holds the vertex and the ε_M shortcut answers.
  if (zeros == 1u || zeros == 2u || zeros == 4u) {
    const TriId u = tri_.neighbour(t, zeros == 1u ? 0 : zeros == 2u ? 1 : 2);
    if (u.valid() && u.index < t.index) t = u;
  }
  return t;
}

TriId BackgroundMesh2d::locate(const Vec2& x, MeshLocateHint2d& hint) const {
  const Vec2 p = clamp(x);
  TriId start(hint.triangle);
  if (start.valid() && tri_.isAlive(start)) {
    const Vec2& a = tri_.point(tri_.vertex(start, 0));
    const Vec2& b = tri_.point(tri_.vertex(start, 1));
    const Vec2& c = tri_.point(tri_.vertex(start, 2));
    const double reach = kHintReach * kHintReach * std::max((b - a).squaredNorm(), (c - a).squaredNorm());
    if ((p - a).squaredNorm() > reach) start = TriId();
  } else {
    start = TriId();
  }
  const TriId t = locateFrom(p, start, hint.rng);
  hint.triangle = t.index;
  return t;
}

// ---- interpolation ----

int BackgroundMesh2d::gather(const Vec2& p, TriId t, BackgroundInterpolation method, std::uint32_t* out) const {
  const std::uint32_t* tv = tri_.triVertices(t);
  if (method == BackgroundInterpolation::Single) {
    int best = 0;
    double bestD = 0;
    for (int i = 0; i < 3; ++i) {
      const double d = (aux_[tv[i]] * (p - tri_.point(VertexId(tv[i])))).squaredNorm();
      if (i == 0 || d < bestD) {
        best = i;
        bestD = d;
      }
    }
    out[0] = tv[best];
    return 1;
  }
  if (method == BackgroundInterpolation::Element) {
    out[0] = tv[0], out[1] = tv[1], out[2] = tv[2];
    return 3;
  }
  // A_o: breadth-first search from t through the triangles whose circumcircle strictly
  // contains p (the conflict region of p: connected, so the search finds all of it).
  std::array<std::uint32_t, kMaxNeighbourhood> in;
  std::array<std::uint32_t, 3 * kMaxNeighbourhood> seen;
  int nIn = 0, nSeen = 0;
  in[nIn++] = t.index;
  seen[nSeen++] = t.index;
  for (int k = 0; k < nIn; ++k) {
    const std::uint32_t* tn = tri_.triNeighbours(TriId(in[k]));
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t u = tn[i];
      if (u == del2d::kNone || std::find(seen.begin(), seen.begin() + nSeen, u) != seen.begin() + nSeen) continue;
      if (nSeen == static_cast<int>(seen.size()) || nIn == kMaxNeighbourhood) continue;
      seen[nSeen++] = u;
      const std::uint32_t* uv = tri_.triVertices(TriId(u));
      if (predicates::incircle(tri_.coords(VertexId(uv[0])), tri_.coords(VertexId(uv[1])),
                               tri_.coords(VertexId(uv[2])), p.data()) > 0)
        in[nIn++] = u;
    }
  }
  int n = 0;
  for (int k = 0; k < nIn; ++k) {
    const std::uint32_t* uv = tri_.triVertices(TriId(in[k]));
    for (int i = 0; i < 3; ++i)
      if (std::find(out, out + n, uv[i]) == out + n) out[n++] = uv[i];
  }
  return n;
}

int BackgroundMesh2d::shortcutOrWeights(const Vec2& p, const std::uint32_t* set, int n, bool useMetric,
                                        double* w) const {
  int best = -1;
  double bestD = epsM_;
  for (int i = 0; i < n; ++i) {
    const std::uint32_t v = set[i];
    const Vec2 dr = aux_[v] * (p - tri_.point(VertexId(v)));
    const double r2 = dr.squaredNorm();
    if (r2 == 0) return i;
    if (useMetric) {
      const double dM = (metric_[v].matrix() * dr).norm();
      if (dM < bestD) {
        bestD = dM;
        best = i;
      }
    }
    w[i] = 1 / r2;
  }
  return best;
}

Metric2d BackgroundMesh2d::blendMetric(const Vec2& p, const std::uint32_t* set, int n) const {
  if (n == 1) return metric_[set[0]];
  double w[kMaxNeighbourhood + 2];
  const int s = shortcutOrWeights(p, set, n, true, w);
  if (s >= 0) return metric_[set[s]];
  Mat2 l = Mat2::Zero();
  double total = 0;
  for (int i = 0; i < n; ++i) {
    l += w[i] * length_[set[i]];
    total += w[i];
  }
  return Metric2d::fromTransformation(symmetrize<2>(Mat2((l / total).inverse())));
}

Mat2 BackgroundMesh2d::blendAux(const Vec2& p, const std::uint32_t* set, int n) const {
  if (!hasAux_) return Mat2::Identity();
  if (n == 1) return aux_[set[0]];
  double w[kMaxNeighbourhood + 2];
  const int s = shortcutOrWeights(p, set, n, valued_, w);
  if (s >= 0) return aux_[set[s]];
  Mat2 a = Mat2::Zero();
  double total = 0;
  for (int i = 0; i < n; ++i) {
    a += w[i] * aux_[set[i]];
    total += w[i];
  }
  return symmetrize<2>(Mat2(a / total));
}

void BackgroundMesh2d::fieldNear(const Vec2& p, TriId near, Metric2d* m, Mat2* aux) const {
  std::uint32_t rng = 0x2545F491u;
  const TriId t = locateFrom(p, near, rng);
  std::uint32_t set[kMaxNeighbourhood + 2];
  const int n = gather(p, t, options_.interpolation, set);
  if (m) *m = blendMetric(p, set, n);
  if (aux) *aux = blendAux(p, set, n);
}

void BackgroundMesh2d::sample(const Vec2& x, MeshLocateHint2d& hint, Metric2d& metric, Mat2& aux) const {
  if (!valued_) failFresh(x);
  const Vec2 p = clamp(x);
  const TriId t = locate(p, hint);
  std::uint32_t set[kMaxNeighbourhood + 2];
  const int n = gather(p, t, options_.interpolation, set);
  metric = blendMetric(p, set, n);
  aux = blendAux(p, set, n);
}

Mat2 BackgroundMesh2d::auxAt(const Vec2& x, MeshLocateHint2d& hint) const {
  if (!hasAux_) return Mat2::Identity();
  const Vec2 p = clamp(x);
  const TriId t = locate(p, hint);
  std::uint32_t set[kMaxNeighbourhood + 2];
  const int n = gather(p, t, options_.interpolation, set);
  return blendAux(p, set, n);
}

int BackgroundMesh2d::interpolationSet(const Vec2& x, MeshLocateHint2d& hint, BackgroundInterpolation method,
                                       std::vector<int>& out) const {
  const Vec2 p = clamp(x);
  const TriId t = locate(p, hint);
  std::uint32_t set[kMaxNeighbourhood + 2];
  const int n = gather(p, t, method, set);
  out.assign(set, set + n);
  return n;
}

// ---- structure ----

BackgroundMesh2d::Inserted BackgroundMesh2d::insertVertex(const Vec2& p, const Metric2d& m, const Mat2& aux,
                                                          bool known, TriId near) {
  const TriId start = near.valid() && tri_.isAlive(near) ? near : TriId();
  const del2d::InsertResult r = del2d::insertPoint(tri_, p, Mat2::Identity(), start);
  Inserted res;
  if (r.status == del2d::InsertStatus::Duplicate) {
    res.vertex = static_cast<int>(r.vertex.index);
  } else if (r.status == del2d::InsertStatus::Inserted) {
    res.vertex = static_cast<int>(r.vertex.index);
    res.created = true;
    const std::size_t nv = tri_.numVertices();
    metric_.resize(nv);
    length_.resize(nv, Mat2::Identity());
    aux_.resize(nv, Mat2::Identity());
    known_.resize(nv, 0);
    metric_[res.vertex] = m;
    length_[res.vertex] = m.inverseMatrix();
    aux_[res.vertex] = aux;
    known_[res.vertex] = known ? 1 : 0;
  }
  return res;
}

void BackgroundMesh2d::appendStar(int v, std::vector<TriId>& out) const {
  const VertexId vid(static_cast<std::uint32_t>(v));
  const TriId first = tri_.vertexTriangle(vid);
  if (!first.valid()) return;
  // Rotate one way (across the edge after v) until back at the start or at the boundary;
  // on the boundary, rotate the other way from the start too.
  TriId t = first;
  do {
    out.push_back(t);
    t = tri_.neighbour(t, kNext[tri_.localIndex(t, vid)]);
  } while (t.valid() && t != first);
  if (t.valid()) return;
  for (t = tri_.neighbour(first, kPrev[tri_.localIndex(first, vid)]); t.valid();
       t = tri_.neighbour(t, kPrev[tri_.localIndex(t, vid)]))
    out.push_back(t);
}

void BackgroundMesh2d::neighbours(int v, std::vector<int>& out) const {
  std::vector<TriId> star;
  appendStar(v, star);
  out.clear();
  for (TriId t : star)
    for (int i = 0; i < 3; ++i) {
      const int w = static_cast<int>(tri_.vertex(t, i).index);
      if (w != v && std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
    }
}

void BackgroundMesh2d::setVertex(int v, const Metric2d& m) {
  metric_[v] = m;
  length_[v] = m.inverseMatrix();
}

void BackgroundMesh2d::intersectVertex(int v, const Metric2d& m) {
  if (intersectInto(metric_[v], m)) length_[v] = metric_[v].inverseMatrix();
}

VertexGraph BackgroundMesh2d::graph() const {
  std::vector<std::array<int, 2>> pairs;
  pairs.reserve(3 * tri_.numTriangles());
  for (std::uint32_t k = 0; k < tri_.triangleSlots(); ++k) {
    const TriId t(k);
    if (!tri_.isAlive(t)) continue;
    const std::uint32_t* tv = tri_.triVertices(t);
    for (int i = 0; i < 3; ++i) {
      const TriId u = tri_.neighbour(t, i);
      if (u.valid() && u.index < k) continue;  // the edge is listed from the other side
      pairs.push_back({static_cast<int>(tv[kNext[i]]), static_cast<int>(tv[kPrev[i]])});
    }
  }
  return makeVertexGraph(vertexCount(), std::move(pairs));
}

int BackgroundMesh2d::smoothGradation(double gamma) {
  if (!valued_) failFresh(bounds_.lo);
  const Modification done{*this};
  const VertexGraph g = graph();
  std::vector<Vec2> d(g.edges.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const int a = g.edges[e][0], b = g.edges[e][1];
    d[e] = point(b) - point(a);
    if (hasAux_) d[e] = (0.5 * (aux_[a] + aux_[b]) * d[e]).eval();  // M_p at the midpoint (eq. 2.13)
  }
  std::vector<std::uint8_t> changed(metric_.size(), 0);
  const int rounds = smoothByEdgeMarking<2>(g, d, gamma, metric_, changed);
  for (std::size_t v = 0; v < metric_.size(); ++v)
    if (changed[v]) length_[v] = metric_[v].inverseMatrix();
  return rounds;
}

void BackgroundMesh2d::forEachVertex(const VertexVisitor& visit) const {
  if (!valued_) return;
  for (int v = 0; v < vertexCount(); ++v) visit(point(v), metric_[v]);
}

void BackgroundMesh2d::modifyVertices(const VertexModifier& modify) {
  if (!valued_) return;
  const Modification done{*this};
  for (int v = 0; v < vertexCount(); ++v) {
    Metric2d m = metric_[v];
    if (modify(point(v), m)) setVertex(v, m);
  }
}

ControlSpaceGrid BackgroundMesh2d::grid() const {
  ControlSpaceGrid g;
  g.dim = 2;
  g.cellSize = 3;
  const int nv = vertexCount();
  g.points.resize(nv);
  for (int v = 0; v < nv; ++v) g.points[v] = Vec3(point(v).x(), point(v).y(), 0);
  for (std::uint32_t k = 0; k < tri_.triangleSlots(); ++k) {
    if (!tri_.isAlive(TriId(k))) continue;
    const std::uint32_t* tv = tri_.triVertices(TriId(k));
    for (int i = 0; i < 3; ++i) g.cells.push_back(static_cast<int>(tv[i]));  // counter-clockwise
    g.cellLevel.push_back(0);
  }
  if (valued_) {
    g.metric.assign(nv, Mat3::Zero());
    g.lengths.assign(nv, Vec3::Zero());
    g.directions.assign(nv, Mat3::Identity());
    for (int v = 0; v < nv; ++v) {
      const MetricAxes<2> a = metric_[v].axes();
      g.metric[v].topLeftCorner<2, 2>() = metric_[v].matrix();
      g.lengths[v].head<2>() = a.lengths;
      g.directions[v].topLeftCorner<2, 2>() = a.directions;
    }
  }
  if (hasAux_) {
    g.parameterization.assign(nv, Mat3::Zero());
    for (int v = 0; v < nv; ++v) g.parameterization[v].topLeftCorner<2, 2>() = aux_[v];
  }
  return g;
}

void BackgroundMesh2d::validate() const {
  const std::string where = "background mesh control space invalid: ";
  del2d::ValidateOptions vo;
  vo.delaunay = true;
  const std::vector<std::string> problems = del2d::validate(tri_, vo);
  if (!problems.empty()) throw MeshingError(where + problems.front());
  const std::size_t nv = tri_.numVertices();
  if (metric_.size() != nv || length_.size() != nv || aux_.size() != nv || known_.size() != nv)
    throw MeshingError(where + "per-vertex arrays do not match the vertex count");
  std::size_t known = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    known += known_[v];
    if (valued_ && !known_[v]) throw MeshingError(where + "vertex " + std::to_string(v) + " carries no metric");
    if (!tri_.vertexTriangle(VertexId(static_cast<std::uint32_t>(v))).valid())
      throw MeshingError(where + "vertex " + std::to_string(v) + " is in no triangle");
    if (known_[v]) {
      const Mat2& m = metric_[v].matrix();
      if (!isSymmetricPositiveDefinite(m))
        throw MeshingError(where + "metric of vertex " + std::to_string(v) + " is not SPD");
      if (!((length_[v] * m - Mat2::Identity()).norm() < 1e-8))
        throw MeshingError(where + "stored inverse of vertex " + std::to_string(v) + " is stale");
    }
    if (!isSymmetricPositiveDefinite(aux_[v]))
      throw MeshingError(where + "parameterization tensor of vertex " + std::to_string(v) + " is not SPD");
  }
  if (!valued_ && known != pending_)
    throw MeshingError(where + "pending point sources (" + std::to_string(pending_) + ") do not match the " +
                       std::to_string(known) + " vertices carrying a metric");
}

}  // namespace aniso
