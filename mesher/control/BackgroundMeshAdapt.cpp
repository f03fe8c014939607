// BackgroundMesh<D>: the adaptation procedures — point sources (sec. 3.4.1), continuous
// sources (3.4.2), parameterization (3.4.3, 2D) and the initialization with extrapolation.
#include <algorithm>
#include <cmath>

#include "mesher/control/BackgroundMesh.h"
#include "mesher/control/TensorDifference.h"
#include "mesher/core/Error.h"
#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/metric/MetricInterpolation.h"

namespace aniso {

namespace {

/// Passes of an adaptation with A_o before it gives up on reaching a fixed point.
constexpr int kMaxAdaptPasses = 16;
/// Ring points are added only across edges longer than l_Mmax by this relative margin.
constexpr double kRingSlack = 1e-9;
/// Largest shift of an interior initial-grid coordinate in 3D, in grid steps.
constexpr double kGridJitter = 0.1;

/// A deterministic pseudo-random number in [0, 1) from grid indices (splitmix64).
double unitHash(int i, int j, int l, int k) {
  std::uint64_t z = (std::uint64_t(i) * 0x9E3779B97F4A7C15ull) ^ (std::uint64_t(j) << 21) ^ (std::uint64_t(l) << 42) ^
                    std::uint64_t(k) * 0xD1B54A32D192ED03ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-53;
}

}  // namespace

template <int D>
bool BackgroundMesh<D>::belowResolution(Elem t, const MetricD& m, const Aux& aux) const {
  double len = kernel_.maxEdgeLength(t, transformation(m, aux));
  const std::uint32_t* tv = kernel_.vertices(t);
  for (int i = 0; i < Kernel::kCorners; ++i)
    if (known_[tv[i]]) len = std::max(len, kernel_.maxEdgeLength(t, transformation(metric_[tv[i]], aux_[tv[i]])));
  return len < options_.minElementMetricLength;
}

template <int D>
bool BackgroundMesh<D>::checkPoint(Elem t, Vec& x) const {
  x = kernel_.centroid(t);
  if (bounds_.contains(x)) return true;
  // An element reaching out of the bounds (towards the box corners) is checked at the
  // bounds point nearest to its centroid, when that point is in the element.
  x = clamp(x);
  return kernel_.closureContains(t, x);
}

template <int D>
int BackgroundMesh<D>::nearVertices(Elem t, std::uint32_t* out) const {
  int n = 0;
  const auto add = [&](Elem u) {
    const std::uint32_t* uv = kernel_.vertices(u);
    for (int i = 0; i < Kernel::kCorners; ++i)
      if (std::find(out, out + n, uv[i]) == out + n) out[n++] = uv[i];
  };
  add(t);
  for (int i = 0; i < Kernel::kCorners; ++i)
    if (kernel_.neighbour(t, i).valid()) add(kernel_.neighbour(t, i));
  return n;
}

template <int D>
typename BackgroundMesh<D>::Vec BackgroundMesh<D>::refinementPoint(Elem t, const Vec& x) const {
  const Vec cc = kernel_.circumcentre(t);
  if (cc.allFinite()) {
    const Vec p = clamp(cc);
    if (kernel_.inSphere(t, p)) return p;
  }
  return x;
}

template <int D>
void BackgroundMesh<D>::refine(const NeedsRefinement& needs, const NewVertexValues& values) {
  std::vector<Elem> work;
  for (int pass = 0; pass < kMaxAdaptPasses; ++pass) {
    work.clear();
    for (std::uint32_t k = 0; k < kernel_.slots(); ++k)
      if (kernel_.isAlive(Elem(k))) work.push_back(Elem(k));
    std::size_t inserted = 0;
    while (!work.empty() && metric_.size() < options_.maxVertices) {
      const Elem t = work.back();
      work.pop_back();
      Vec x;
      if (!kernel_.isAlive(t) || !checkPoint(t, x) || !needs(t, x)) continue;
      Vec p = refinementPoint(t, x);
      MetricD m;
      Aux aux;
      bool known = values(p, t, m, aux);
      KernelInsertion ins = insertVertex(p, m, aux, known, t);
      if (!ins.created && p != x) {  // the clamped circumcentre is an existing vertex
        p = x;
        known = values(p, t, m, aux);
        ins = insertVertex(p, m, aux, known, t);
      }
      if (!ins.created) continue;  // x is a vertex of t: nothing to refine there
      ++inserted;
      kernel_.appendCreated(ins.vertex, work);
    }
    // A_t and A_s sets of an element never change unless the element is replaced (and
    // then its replacements are checked): one pass is a fixed point. A_o sets reach
    // across the cavity, so a pass may spoil elements checked earlier.
    if (inserted == 0 || options_.interpolation != BackgroundInterpolation::Neighbourhood) break;
  }
}

// ---- point sources (sec. 3.4.1) ----

template <int D>
void BackgroundMesh<D>::insertDiscrete(const Vec& x, const MetricD& m) {
  if (!x.allFinite()) throw MeshingError("background mesh control space: point source at a non-finite point");
  const Modification done{*this};
  if (valued_)
    insertUpdate(clamp(x), m);
  else
    insertInitial(clamp(x), m);
}

template <int D>
int BackgroundMesh<D>::closeVertex(const Vec& p, Elem t, const Mat& tq, bool onlyKnown) const {
  std::uint32_t set[kSetBuffer];
  const int n = nearVertices(t, set);
  int best = -1;
  double bestD = epsM_;
  for (int i = 0; i < n; ++i) {
    if (onlyKnown && !known_[set[i]]) continue;
    const double d = (tq * (point(static_cast<int>(set[i])) - p)).norm();
    if (d < bestD) {
      bestD = d;
      best = static_cast<int>(set[i]);
    }
  }
  return best;
}

template <int D>
void BackgroundMesh<D>::insertInitial(const Vec& p, const MetricD& m) {
  std::uint32_t rng = 0x2545F491u;
  const Elem t = locateFrom(p, Elem(), rng);
  Aux ap{};
  if constexpr (kParameterized) {
    std::uint32_t set[kSetBuffer];
    const int n = gather(p, t, options_.interpolation, set);
    ap = auxExact_ ? auxExact_(p) : blendAux(p, set, n);
  }
  // Proximity (step 1): merge into a vertex carrying a metric closer than ε_M in M_Q.
  const int best = closeVertex(p, t, transformation(m, ap), true);
  if (best >= 0) {
    intersectVertex(best, m);
    return;
  }
  const KernelInsertion ins = insertVertex(p, m, ap, true, t);
  if (ins.created) {
    ++pending_;
  } else if (ins.vertex >= 0) {  // exactly on a vertex (ε_M = 0)
    if (known_[ins.vertex]) {
      intersectVertex(ins.vertex, m);
    } else {
      setVertex(ins.vertex, m);
      known_[ins.vertex] = 1;
      ++pending_;
    }
  }
}

template <int D>
void BackgroundMesh<D>::insertUpdate(const Vec& p, const MetricD& m) {
  std::uint32_t rng = 0x2545F491u;
  const Elem t = locateFrom(p, Elem(), rng);
  std::uint32_t set[kSetBuffer];
  const int n = gather(p, t, options_.interpolation, set);
  const MetricD current = blendMetric(p, set, n);
  const Aux ap = blendAux(p, set, n);
  if (metricDifference(m, current) < epsDelta_) return;        // step 2
  const MetricD updated = intersect(m, current);               // step 3
  if (metricDifference(updated, current) < epsDelta_) return;  // step 4
  const Mat tq = transformation(m, ap);
  // Proximity of control vertices (3.4.1 step 1).
  const int best = closeVertex(p, t, tq, false);
  if (best >= 0) {
    intersectVertex(best, m);
    return;
  }
  // Step 5, size sensitivity: a containing element already short in M_Q only has its
  // vertices intersected (as the quadtree's leaf corners); a long one is "split" by
  // inserting Q itself, with a ring that keeps the change local.
  if (kernel_.maxEdgeLength(t, tq) <= lMax_ || metric_.size() >= options_.maxVertices) {
    for (int i = 0; i < Kernel::kCorners; ++i) intersectVertex(static_cast<int>(kernel_.vertices(t)[i]), m);
    return;
  }
  const KernelInsertion ins = insertVertex(p, updated, auxExact_ ? auxExact_(p) : ap, true, t);
  if (!ins.created) {
    if (ins.vertex >= 0) intersectVertex(ins.vertex, m);
    return;
  }
  addRing(ins.vertex, p, current, tq);
}

template <int D>
void BackgroundMesh<D>::addRing(int q, const Vec& x, const MetricD& before, const Mat& tq) {
  // Every edge from Q longer than l_Mmax in M_Q gets a vertex at metric distance l_Mmax
  // from Q carrying the field as it was before Q (eq. 2.18 between the old value at Q and
  // the far vertex): the mesh counterpart of the quadtree's splits down to leaves of
  // l_Mmax around the source, so the source changes the field only within that distance.
  std::vector<int> around;
  for (int round = 0; round < options_.maxRingRounds; ++round) {
    neighbours(q, around);
    int added = 0;
    for (int w : around) {
      if (metric_.size() >= options_.maxVertices) return;
      const Vec d = point(w) - x;
      const double len = (tq * d).norm();
      if (len <= lMax_ * (1 + kRingSlack)) continue;
      const double s = lMax_ / len;
      const Vec r = clamp(x + s * d);
      const MetricD mr = interpolate(before, metric_[w], s);
      Aux ar{};
      if constexpr (kParameterized) ar = auxExact_ ? auxExact_(r) : Mat((1 - s) * aux_[q] + s * aux_[w]);
      if (insertVertex(r, mr, ar, true, kernel_.vertexElement(static_cast<std::uint32_t>(q))).created) ++added;
    }
    if (added == 0) return;
  }
}

template <int D>
void BackgroundMesh<D>::initializeVertices() {
  if (pending_ == 0) {
    if (valued_) return;
    throw MeshingError("background mesh control space: no metric source to initialize the control vertices from");
  }
  const Modification done{*this};
  const VertexGraph g = graph();
  std::vector<double> len(g.edges.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) len[e] = (point(g.edges[e][1]) - point(g.edges[e][0])).norm();
  extrapolateLayers<D>(g, len, known_, metric_);
  for (std::size_t v = 0; v < metric_.size(); ++v) length_[v] = metric_[v].inverseMatrix();
  valued_ = true;
  pending_ = 0;
}

// ---- continuous sources (sec. 3.4.2) ----

template <int D>
void BackgroundMesh<D>::addInitialGrid() {
  const Vec size = bounds_.size();
  const double step = size.maxCoeff() / (options_.initialGrid - 1);
  int n[D];
  for (int k = 0; k < D; ++k) n[k] = size(k) > 0 ? std::max(2, static_cast<int>(std::lround(size(k) / step)) + 1) : 1;
  Elem near;
  int idx[3] = {0, 0, 0};  // the grid index, axis 0 fastest
  for (;;) {
    Vec f;
    for (int k = 0; k < D; ++k) {
      f(k) = n[k] > 1 ? double(idx[k]) / (n[k] - 1) : 0.5;
      // 3D: interior coordinates are shifted by up to ±kGridJitter of a step: the eight
      // cospherical corners of every cell of an exact grid would send every in-sphere
      // test of the insertion to exact arithmetic (measured: 60 % of the build time).
      if (D == 3 && idx[k] > 0 && idx[k] < n[k] - 1)
        f(k) += kGridJitter * (2 * unitHash(idx[0], idx[1], idx[2], k) - 1) / (n[k] - 1);
    }
    const Vec p = clamp(bounds_.lo + f.cwiseProduct(size));
    const KernelInsertion ins = insertVertex(p, MetricD(), auxExact_ ? auxExact_(p) : identityAux(), false, near);
    if (ins.created) near = kernel_.vertexElement(static_cast<std::uint32_t>(ins.vertex));
    int k = 0;
    while (k < D && ++idx[k] == n[k]) idx[k++] = 0;
    if (k == D) return;
  }
}

template <int D>
void BackgroundMesh<D>::setContinuous(const MetricFn& source) {
  const Modification done{*this};
  const bool had = valued_;
  const bool exact = !had && pending_ == 0;  // the field must reproduce the source
  if (!had) addInitialGrid();
  for (int v = 0; v < vertexCount(); ++v) {
    const MetricD s = source(clamp(point(v)));
    setVertex(v, known_[v] ? intersect(metric_[v], s) : s);
    known_[v] = 1;
  }
  valued_ = true;
  pending_ = 0;
  const auto fails = [&](Elem t, const Vec& x) {
    const MetricD target = source(x);
    std::uint32_t set[kSetBuffer];
    const int n = gather(x, t, options_.interpolation, set);
    const MetricD field = blendMetric(x, set, n);
    // Fresh: the field must reproduce the source. Valued: only where the source asks for
    // a finer metric than the field (where earlier sources are finer, refining could
    // never bring the two closer).
    const MetricD goal = exact ? target : intersect(field, target);
    if (metricDifference(goal, field) <= epsDelta_) return false;
    return !belowResolution(t, target, blendAux(x, set, n));
  };
  const auto needs = [&](Elem t, const Vec& x) {
    if (fails(t, x)) return true;
    if (options_.check == BackgroundCheck::Centroid) return false;
    const std::uint32_t* tv = kernel_.vertices(t);
    for (const auto& e : Kernel::kEdges) {
      const Vec mid = 0.5 * (kernel_.point(tv[e[0]]) + kernel_.point(tv[e[1]]));
      if (bounds_.contains(mid) && fails(t, mid)) return true;
    }
    return false;
  };
  const auto values = [&](const Vec& p, Elem near, MetricD& m, Aux& aux) {
    // The field only where it is needed: for the intersection, or for M_p (fieldNear
    // only reads the mesh, so it may come before the source).
    MetricD field;
    if (kParameterized || !exact) fieldNear(p, near, &field, &aux);
    const MetricD s = source(p);
    m = exact ? s : intersect(field, s);
    if (auxExact_) aux = auxExact_(p);
    return true;
  };
  refine(needs, values);
}

// ---- parameterization (sec. 3.4.3) ----

template <int D>
void BackgroundMesh<D>::adaptAux(const MatFn& exact)
  requires(D == 2)
{
  const Modification done{*this};
  for (int v = 0; v < vertexCount(); ++v) aux_[v] = exact(clamp(point(v)));
  hasAux_ = true;
  auxExact_ = exact;
  const auto needs = [&](Elem t, const Vec& c) {  // the check point of 3.3.3 only
    const Mat centre = exact(c);
    std::uint32_t set[kSetBuffer];
    const int n = gather(c, t, options_.interpolation, set);
    double worst = tensorDifference<D>(centre, blendAux(c, set, n));
    for (int i = 0; i < Kernel::kCorners; ++i)
      worst = std::max(worst, tensorDifference<D>(centre, aux_[kernel_.vertices(t)[i]]));
    if (worst <= epsDelta_) return false;
    return !(valued_ && belowResolution(t, blendMetric(c, set, n), centre));
  };
  const auto values = [&](const Vec& p, Elem near, MetricD& m, Mat& aux) {
    aux = exact(p);
    if (!valued_) return false;  // extrapolated by initializeVertices
    fieldNear(p, near, &m, nullptr);
    return true;
  };
  refine(needs, values);
}

template void BackgroundMesh<2>::insertDiscrete(const Vec2&, const Metric2d&);
template void BackgroundMesh<2>::initializeVertices();
template void BackgroundMesh<2>::setContinuous(const MetricFn&);
template void BackgroundMesh<2>::adaptAux(const MatFn&);
template void BackgroundMesh<3>::insertDiscrete(const Vec3&, const Metric3d&);
template void BackgroundMesh<3>::initializeVertices();
template void BackgroundMesh<3>::setContinuous(const MetricFn&);

}  // namespace aniso
