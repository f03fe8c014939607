// BackgroundMesh<D>: construction, point location, interpolation (sec. 3.4.5), vertex
// insertion, vertex-wide operations, export and validation. The adaptation procedures
// (3.4.1–3.4.3) are in BackgroundMeshAdapt.cpp, the per-dimension kernels in
// BackgroundMeshKernel2d.cpp / 3d.cpp.
#include "mesher/control/BackgroundMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "mesher/control/ControlSpaceGridTensors.h"
#include "mesher/core/Error.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/metric/SymmetricEigen.h"

namespace aniso {

namespace {

template <int D>
std::string pointText(const Eigen::Matrix<double, D, 1>& x) {
  std::ostringstream s;
  s.precision(10);
  s << "(" << x(0);
  for (int k = 1; k < D; ++k) s << ", " << x(k);
  s << ")";
  return s.str();
}

/// A query within this many edge lengths of the hint's first vertex starts its walk at
/// the hint; farther ones at the seeding tree.
constexpr double kHintReach = 2.0;

/// Σ w_i x[set_i] / Σ w_i (eq. 3.2), summed in the order of the set.
template <class M>
M weightedMean(const std::vector<M>& x, const std::uint32_t* set, const double* w, int n) {
  M sum = M::Zero();
  double total = 0;
  for (int i = 0; i < n; ++i) {
    sum += w[i] * x[set[i]];
    total += w[i];
  }
  return M(sum / total);
}

template <int D>
const Box<D>& checkedBounds(const Box<D>& b) {
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

template <int D>
BackgroundMesh<D>::BackgroundMesh(const Box<D>& bounds, const SizingParameters& params,
                                  const BackgroundMeshOptions& options)
    : bounds_(checkedBounds(bounds)),
      epsM_(params.metricDistanceEps),
      epsDelta_(params.metricDifferenceEps),
      lMax_(params.adaptLengthMax),
      options_(options),
      kernel_((checkBackgroundParameters(params, options), bounds_), options) {
  const std::size_t nv = kernel_.numVertices();
  metric_.resize(nv);
  length_.assign(nv, Mat::Identity());
  aux_.assign(nv, identityAux());
  known_.assign(nv, 0);
}

template <int D>
void BackgroundMesh<D>::setInterpolation(BackgroundInterpolation method) {
  options_.interpolation = method;
  ++revision_;
}

template <int D>
void BackgroundMesh<D>::failFresh(const Vec& x) const {
  throw MeshingError("background mesh control space: metric requested at " + pointText<D>(x) +
                     " before the control vertices carry a metric (set a continuous source or call "
                     "initializeControlVertices)");
}

// ---- point location ----

template <int D>
typename BackgroundMesh<D>::Elem BackgroundMesh<D>::locateFrom(const Vec& p, Elem start, std::uint32_t& rng) const {
  const Elem t = kernel_.locate(p, start, rng);
  if (!t.valid()) throw MeshingError("background mesh control space: point location failed at " + pointText<D>(p));
  return t;
}

template <int D>
typename BackgroundMesh<D>::Elem BackgroundMesh<D>::locate(const Vec& x, MeshLocateHint<D>& hint) const {
  const Vec p = clamp(x);
  Elem start(hint.element);
  if (start.valid() && kernel_.isAlive(start)) {
    const std::uint32_t* tv = kernel_.vertices(start);
    const Vec a = kernel_.point(tv[0]);
    double edge = 0;
    for (int i = 1; i < Kernel::kCorners; ++i) edge = std::max(edge, (kernel_.point(tv[i]) - a).squaredNorm());
    if ((p - a).squaredNorm() > kHintReach * kHintReach * edge) start = Elem();
  } else {
    start = Elem();
  }
  const Elem t = locateFrom(p, start, hint.rng);
  hint.element = t.index;
  return t;
}

// ---- interpolation ----

template <int D>
int BackgroundMesh<D>::gather(const Vec& p, Elem t, BackgroundInterpolation method, std::uint32_t* out) const {
  constexpr int kCorners = Kernel::kCorners;
  const std::uint32_t* tv = kernel_.vertices(t);
  if (method == BackgroundInterpolation::Single) {
    int best = 0;
    double bestD = 0;
    for (int i = 0; i < kCorners; ++i) {
      const double d = inR(tv[i], p - kernel_.point(tv[i])).squaredNorm();
      if (i == 0 || d < bestD) {
        best = i;
        bestD = d;
      }
    }
    out[0] = tv[best];
    return 1;
  }
  if (method == BackgroundInterpolation::Element) {
    for (int i = 0; i < kCorners; ++i) out[i] = tv[i];
    return kCorners;
  }
  // A_o: breadth-first search from t through the elements whose circumsphere strictly
  // contains p (the conflict region of p: connected, so the search finds all of it).
  std::array<std::uint32_t, kMaxNeighbourhood> in;
  std::array<std::uint32_t, kCorners * kMaxNeighbourhood> seen;
  int nIn = 0, nSeen = 0;
  in[nIn++] = t.index;
  seen[nSeen++] = t.index;
  for (int k = 0; k < nIn; ++k) {
    for (int i = 0; i < kCorners; ++i) {
      const Elem u = kernel_.neighbour(Elem(in[k]), i);
      if (!u.valid() || std::find(seen.begin(), seen.begin() + nSeen, u.index) != seen.begin() + nSeen) continue;
      if (nSeen == static_cast<int>(seen.size()) || nIn == kMaxNeighbourhood) continue;
      seen[nSeen++] = u.index;
      if (kernel_.inSphere(u, p)) in[nIn++] = u.index;
    }
  }
  int n = 0;
  for (int k = 0; k < nIn; ++k) {
    const std::uint32_t* uv = kernel_.vertices(Elem(in[k]));
    for (int i = 0; i < kCorners; ++i)
      if (std::find(out, out + n, uv[i]) == out + n) out[n++] = uv[i];
  }
  return n;
}

template <int D>
int BackgroundMesh<D>::shortcutOrWeights(const Vec& p, const std::uint32_t* set, int n, bool useMetric,
                                         double* w) const {
  int best = -1;
  double bestD = epsM_;
  for (int i = 0; i < n; ++i) {
    const std::uint32_t v = set[i];
    const Vec dr = inR(v, p - kernel_.point(v));
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

template <int D>
typename BackgroundMesh<D>::MetricD BackgroundMesh<D>::blendMetric(const Vec& p, const std::uint32_t* set,
                                                                   int n) const {
  if (n == 1) return metric_[set[0]];
  double w[kSetBuffer];
  const int s = shortcutOrWeights(p, set, n, true, w);
  if (s >= 0) return metric_[set[s]];
  return MetricD::fromTransformation(symmetrize<D>(Mat(weightedMean(length_, set, w, n).inverse())));
}

template <int D>
typename BackgroundMesh<D>::Aux BackgroundMesh<D>::blendAux(const Vec& p, const std::uint32_t* set, int n) const {
  if constexpr (!kParameterized) {
    return {};
  } else {
    if (!hasAux_) return Mat::Identity();
    if (n == 1) return aux_[set[0]];
    double w[kSetBuffer];
    const int s = shortcutOrWeights(p, set, n, valued_, w);
    if (s >= 0) return aux_[set[s]];
    return symmetrize<D>(weightedMean(aux_, set, w, n));
  }
}

template <int D>
void BackgroundMesh<D>::fieldNear(const Vec& p, Elem near, MetricD* m, Aux* aux) const {
  std::uint32_t rng = 0x2545F491u;
  const Elem t = locateFrom(p, near, rng);
  std::uint32_t set[kSetBuffer];
  const int n = gather(p, t, options_.interpolation, set);
  if (m) *m = blendMetric(p, set, n);
  if (aux) *aux = blendAux(p, set, n);
}

template <int D>
void BackgroundMesh<D>::sample(const Vec& x, MeshLocateHint<D>& hint, MetricD& metric, Mat& aux) const
  requires(D == 2)
{
  if (!valued_) failFresh(x);
  const Vec p = clamp(x);
  const Elem t = locate(p, hint);
  std::uint32_t set[kSetBuffer];
  const int n = gather(p, t, options_.interpolation, set);
  metric = blendMetric(p, set, n);
  aux = blendAux(p, set, n);
}

template <int D>
typename BackgroundMesh<D>::MetricD BackgroundMesh<D>::metricAt(const Vec& x, MeshLocateHint<D>& hint) const
  requires(D == 3)
{
  if (!valued_) failFresh(x);
  const Vec p = clamp(x);
  const Elem t = locate(p, hint);
  std::uint32_t set[kSetBuffer];
  return blendMetric(p, set, gather(p, t, options_.interpolation, set));
}

template <int D>
typename BackgroundMesh<D>::Mat BackgroundMesh<D>::auxAt(const Vec& x, MeshLocateHint<D>& hint) const
  requires(D == 2)
{
  if (!hasAux_) return Mat::Identity();
  const Vec p = clamp(x);
  const Elem t = locate(p, hint);
  std::uint32_t set[kSetBuffer];
  const int n = gather(p, t, options_.interpolation, set);
  return blendAux(p, set, n);
}

template <int D>
int BackgroundMesh<D>::interpolationSet(const Vec& x, MeshLocateHint<D>& hint, BackgroundInterpolation method,
                                        std::vector<int>& out) const {
  const Vec p = clamp(x);
  const Elem t = locate(p, hint);
  std::uint32_t set[kSetBuffer];
  const int n = gather(p, t, method, set);
  out.assign(set, set + n);
  return n;
}

// ---- structure ----

template <int D>
KernelInsertion BackgroundMesh<D>::insertVertex(const Vec& p, const MetricD& m, const Aux& aux, bool known,
                                                Elem near) {
  const KernelInsertion res = kernel_.insert(p, near);
  if (res.created) {
    const std::size_t nv = kernel_.numVertices();
    metric_.resize(nv);
    length_.resize(nv, Mat::Identity());
    aux_.resize(nv, identityAux());
    known_.resize(nv, 0);
    metric_[res.vertex] = m;
    length_[res.vertex] = m.inverseMatrix();
    aux_[res.vertex] = aux;
    known_[res.vertex] = known ? 1 : 0;
  }
  return res;
}

template <int D>
void BackgroundMesh<D>::neighbours(int v, std::vector<int>& out) const {
  std::vector<Elem> star;
  kernel_.appendStar(v, star);
  out.clear();
  for (Elem t : star)
    for (int i = 0; i < Kernel::kCorners; ++i) {
      const int w = static_cast<int>(kernel_.vertices(t)[i]);
      if (w != v && std::find(out.begin(), out.end(), w) == out.end()) out.push_back(w);
    }
}

template <int D>
void BackgroundMesh<D>::setVertex(int v, const MetricD& m) {
  metric_[v] = m;
  length_[v] = m.inverseMatrix();
}

template <int D>
void BackgroundMesh<D>::intersectVertex(int v, const MetricD& m) {
  if (intersectInto(metric_[v], m)) length_[v] = metric_[v].inverseMatrix();
}

template <int D>
VertexGraph BackgroundMesh<D>::graph() const {
  return makeVertexGraph(vertexCount(), kernel_.edgePairs());
}

template <int D>
int BackgroundMesh<D>::smoothGradation(double gamma) {
  if (!valued_) failFresh(bounds_.lo);
  const Modification done{*this};
  const VertexGraph g = graph();
  std::vector<Vec> d(g.edges.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const int a = g.edges[e][0], b = g.edges[e][1];
    d[e] = point(b) - point(a);
    if constexpr (kParameterized)
      if (hasAux_) d[e] = (0.5 * (aux_[a] + aux_[b]) * d[e]).eval();  // M_p at the midpoint (eq. 2.13)
  }
  std::vector<std::uint8_t> changed(metric_.size(), 0);
  const int rounds = smoothByEdgeMarking<D>(g, d, gamma, metric_, changed);
  for (std::size_t v = 0; v < metric_.size(); ++v)
    if (changed[v]) length_[v] = metric_[v].inverseMatrix();
  return rounds;
}

template <int D>
void BackgroundMesh<D>::forEachVertex(const VertexVisitor& visit) const {
  if (!valued_) return;
  for (int v = 0; v < vertexCount(); ++v) visit(point(v), metric_[v]);
}

template <int D>
void BackgroundMesh<D>::modifyVertices(const VertexModifier& modify) {
  if (!valued_) return;
  const Modification done{*this};
  for (int v = 0; v < vertexCount(); ++v) {
    MetricD m = metric_[v];
    if (modify(point(v), m)) setVertex(v, m);
  }
}

template <int D>
ControlSpaceGrid BackgroundMesh<D>::grid() const {
  ControlSpaceGrid g;
  g.dim = D;
  g.cellSize = Kernel::kCorners;
  const int nv = vertexCount();
  g.points.assign(nv, Vec3::Zero());
  for (int v = 0; v < nv; ++v) g.points[v].template head<D>() = point(v);
  for (std::uint32_t k = 0; k < kernel_.slots(); ++k) {
    if (!kernel_.isAlive(Elem(k))) continue;
    const std::uint32_t* tv = kernel_.vertices(Elem(k));
    // 2D counter-clockwise, 3D orient3d > 0: the VTK orders
    for (int i = 0; i < Kernel::kCorners; ++i) g.cells.push_back(static_cast<int>(tv[i]));
    g.cellLevel.push_back(0);
  }
  if (valued_) setGridTensors<D>(g, metric_);
  if constexpr (kParameterized)
    if (hasAux_) setGridParameterization<D>(g, aux_);
  return g;
}

template <int D>
void BackgroundMesh<D>::validate() const {
  const std::string where = "background mesh control space invalid: ";
  const std::vector<std::string> problems = kernel_.validate();
  if (!problems.empty()) throw MeshingError(where + problems.front());
  const std::size_t nv = kernel_.numVertices();
  if (metric_.size() != nv || length_.size() != nv || aux_.size() != nv || known_.size() != nv)
    throw MeshingError(where + "per-vertex arrays do not match the vertex count");
  std::size_t known = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    known += known_[v];
    if (valued_ && !known_[v]) throw MeshingError(where + "vertex " + std::to_string(v) + " carries no metric");
    if (!kernel_.vertexElement(static_cast<std::uint32_t>(v)).valid())
      throw MeshingError(where + "vertex " + std::to_string(v) + " is in no " + Kernel::kElementName);
    if (known_[v]) {
      const Mat& m = metric_[v].matrix();
      if (!isSymmetricPositiveDefinite(m))
        throw MeshingError(where + "metric of vertex " + std::to_string(v) + " is not SPD");
      if (!((length_[v] * m - Mat::Identity()).norm() < 1e-8))
        throw MeshingError(where + "stored inverse of vertex " + std::to_string(v) + " is stale");
    }
    if constexpr (kParameterized)
      if (!isSymmetricPositiveDefinite(aux_[v]))
        throw MeshingError(where + "parameterization tensor of vertex " + std::to_string(v) + " is not SPD");
  }
  if (!valued_ && known != pending_)
    throw MeshingError(where + "pending point sources (" + std::to_string(pending_) + ") do not match the " +
                       std::to_string(known) + " vertices carrying a metric");
}

template class BackgroundMesh<2>;
template class BackgroundMesh<3>;

}  // namespace aniso
