// TreeControlSpace<D>: field interpolation, split hooks, point sources (3.3.1), continuous
// sources (3.3.2) and the parameterization adaptation (3.3.3). Vertex-wide operations
// (initialization, smoothing, export, validation) are in TreeControlSpaceVertices.cpp.
#include "mesher/control/TreeControlSpace.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mesher/control/TensorDifference.h"
#include "mesher/core/Error.h"
#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/metric/SymmetricEigen.h"

namespace aniso {
namespace {

/// Piecewise-linear hat of grid digit d (0, 1, 2) on [0, 1] with nodes 0, ½, 1.
inline double hat(int d, double t) {
  switch (d) {
    case 0: return t < 0.5 ? 1 - 2 * t : 0;
    case 1: return 1 - std::abs(2 * t - 1);
    default: return t > 0.5 ? 2 * t - 1 : 0;
  }
}

template <int D>
std::string pointText(const Eigen::Matrix<double, D, 1>& x) {
  std::ostringstream s;
  s.precision(10);
  s << "(";
  for (int k = 0; k < D; ++k) s << (k ? ", " : "") << x(k);
  s << ")";
  return s.str();
}

}  // namespace

template <int D>
TreeControlSpace<D>::TreeControlSpace(const Box<D>& box, const SizingParameters& params, const TreeLimits& limits)
    : tree_(box, limits.maxLevel),
      epsM_(params.metricDistanceEps),
      epsDelta_(params.metricDifferenceEps),
      lMax_(params.adaptLengthMax),
      limits_(limits) {
  if (!(std::isfinite(epsM_) && epsM_ >= 0))
    throw InputError("control space: metric distance threshold epsilon_M must be finite and >= 0");
  if (!(std::isfinite(epsDelta_) && epsDelta_ > 0))
    throw InputError("control space: metric difference threshold epsilon_delta must be finite and > 0");
  if (!(std::isfinite(lMax_) && lMax_ > 0))
    throw InputError("control space: adaptation length threshold l_Mmax must be finite and > 0");
  if (!(std::isfinite(limits.minLeafMetricLength) && limits.minLeafMetricLength >= 0))
    throw InputError("control space: minLeafMetricLength must be finite and >= 0");
  metric_.resize(tree_.vertexCount());
  length_.assign(tree_.vertexCount(), Mat::Identity());
  sourceHead_.assign(tree_.nodeCount(), -1);
}

template <int D>
template <class Get>
typename TreeControlSpace<D>::Mat TreeControlSpace<D>::blend(int leaf, const Vec& t, const Get& value) const {
  const auto& c = tree_.corners(leaf);
  Mat r = Mat::Zero();
  for (int i = 0; i < Tree::kCorners; ++i) {
    double w = 1;
    for (int k = 0; k < D; ++k) w *= ((i >> k) & 1) ? t(k) : 1 - t(k);
    r += w * value(c[i]);
  }
  if (!tree_.hasExtras(leaf)) return r;
  for (int s = 0; s < Tree::kExtraSlots; ++s) {
    const int v = tree_.extra(leaf, s);
    if (v == Tree::kNone) continue;
    const auto& d = Tree::slotDigits(s);
    double phi = 1;
    for (int k = 0; k < D && phi > 0; ++k) phi *= hat(d[k], t(k));
    if (!(phi > 0)) continue;
    std::array<int, 4> sc;
    const int n = Tree::slotCorners(s, sc);
    Mat base = Mat::Zero();
    for (int j = 0; j < n; ++j) base += value(c[sc[j]]);
    r += phi * (value(v) - base / n);
  }
  return r;
}

template <int D>
Metric<D> TreeControlSpace<D>::metricIn(int leaf, const Vec& local) const {
  const Mat l = blend(leaf, local, [this](int v) -> const Mat& { return length_[v]; });
  return Metric<D>::fromTransformation(symmetrize<D>(l.inverse()));
}

template <int D>
typename TreeControlSpace<D>::Mat TreeControlSpace<D>::auxIn(int leaf, const Vec& local) const {
  if (!hasAux_) return Mat::Identity();
  return symmetrize<D>(blend(leaf, local, [this](int v) -> const Mat& { return aux_[v]; }));
}

template <int D>
void TreeControlSpace<D>::failFresh(const Vec& x) const {
  throw MeshingError("control space: metric requested at " + pointText<D>(x) +
                     " before the control vertices carry a metric (set a continuous source or call "
                     "initializeControlVertices)");
}

template <int D>
Metric<D> TreeControlSpace<D>::metricAt(const Vec& x) const {
  if (!valued_) failFresh(x);
  Vec local;
  const int leaf = tree_.locate(x, local);
  return metricIn(leaf, local);
}

template <int D>
typename TreeControlSpace<D>::Mat TreeControlSpace<D>::auxAt(const Vec& x) const {
  if (!hasAux_) return Mat::Identity();
  Vec local;
  const int leaf = tree_.locate(x, local);
  return auxIn(leaf, local);
}

template <int D>
void TreeControlSpace<D>::sample(const Vec& x, Metric<D>& metric, Mat& aux) const {
  if (!valued_) failFresh(x);
  Vec local;
  const int leaf = tree_.locate(x, local);
  metric = metricIn(leaf, local);
  aux = auxIn(leaf, local);
}

template <int D>
double TreeControlSpace<D>::maxEdgeMetricLength(int leaf, const Metric<D>& m, const Mat& aux) const {
  const Vec size = tree_.nodeSize(leaf);
  const Mat t = m.matrix() * aux;
  double len = 0;
  for (int k = 0; k < D; ++k) len = std::max(len, size(k) * t.col(k).norm());
  return len;
}

template <int D>
bool TreeControlSpace<D>::belowResolution(int leaf, const Metric<D>& centre) const {
  const Vec half = Vec::Constant(0.5);
  double len = maxEdgeMetricLength(leaf, centre, auxIn(leaf, half));
  for (int v : tree_.corners(leaf))
    len = std::max(len, maxEdgeMetricLength(leaf, metric_[v], hasAux_ ? aux_[v] : Mat::Identity()));
  return len < limits_.minLeafMetricLength;
}

template <int D>
void TreeControlSpace<D>::setVertex(int v, const Metric<D>& m) {
  metric_[v] = m;
  length_[v] = m.inverseMatrix();
}

template <int D>
void TreeControlSpace<D>::intersectVertex(int v, const Metric<D>& m) {
  if (intersectInto(metric_[v], m)) {
    length_[v] = metric_[v].inverseMatrix();
    ++revision_;
  }
}

template <int D>
bool TreeControlSpace<D>::splitLeaf(int leaf) {
  return tree_.split(
      leaf, [this](int v, int l, const Vec& local) { onNewVertex(v, l, local); },
      [this](int n) { onSplit(n); });
}

template <int D>
void TreeControlSpace<D>::onNewVertex(int v, int leaf, const Vec& local) {
  metric_.resize(v + 1);
  length_.resize(v + 1, Mat::Identity());
  if (hasAux_) {
    const Mat a = auxExact_ ? auxExact_(tree_.point(v)) : auxIn(leaf, local);
    aux_.resize(v + 1);
    aux_[v] = a;
  }
  if (!valued_) return;
  Metric<D> m = metricIn(leaf, local);
  if (continuous_) {
    const Metric<D> s = (*continuous_)(tree_.point(v));
    m = continuousExact_ ? s : intersect(m, s);
  }
  setVertex(v, m);
}

template <int D>
void TreeControlSpace<D>::onSplit(int node) {
  const int first = tree_.firstChild(node);
  sourceHead_.resize(tree_.nodeCount(), -1);
  // Pending point sources move to the children (3.3.1: "placed into proper sub-elements").
  for (int s = sourceHead_[node]; s != -1;) {
    const int next = sources_[s].next;
    // The children are leaves at this point, so the leaf of the source is one of them.
    const int target = tree_.locate(sources_[s].x);
    sources_[s].next = sourceHead_[target];
    sourceHead_[target] = s;
    s = next;
  }
  sourceHead_[node] = -1;
  if (newLeaves_)
    for (int c = 0; c < Tree::kCorners; ++c) newLeaves_->push_back(first + c);
}

template <int D>
void TreeControlSpace<D>::insertDiscrete(const Vec& x, const Metric<D>& m) {
  if (!x.allFinite()) throw MeshingError("control space: point source at a non-finite point " + pointText<D>(x));
  if (valued_)
    insertUpdate(x, m);
  else
    insertInitial(x, m);
  ++revision_;
}

template <int D>
void TreeControlSpace<D>::insertInitial(const Vec& x, const Metric<D>& m) {
  Vec local;
  int leaf = tree_.locate(x, local);
  const Box<D> box = tree_.box();
  const Vec xc = x.cwiseMax(box.lo).cwiseMin(box.hi);
  const Mat t = m.matrix() * auxIn(leaf, local);
  // Proximity of point sources: combine with a pending source closer than ε_M; the merged
  // metric is compared with the others at the leaf's next check.
  for (int s = sourceHead_[leaf]; s != -1; s = sources_[s].next) {
    if ((t * (sources_[s].x - xc)).norm() < epsM_) {
      if (intersectInto(sources_[s].m, m)) sources_[s].checked = false;
      return;
    }
  }
  sources_.push_back({xc, m, sourceHead_[leaf]});
  sourceHead_[leaf] = static_cast<int>(sources_.size()) - 1;
  ++pending_;
  // Size sensitivity and metric difference, recursively in the sub-elements. A leaf that
  // passes, or cannot split (deepest level), has its sources marked checked.
  std::vector<int> work{leaf};
  while (!work.empty()) {
    const int n = work.back();
    work.pop_back();
    if (!tree_.isLeaf(n)) continue;
    const int before = tree_.nodeCount();
    if (!initialSplitNeeded(n) || !splitLeaf(n)) {
      markChecked(n);
      continue;
    }
    for (int c = before; c < tree_.nodeCount(); ++c)
      if (tree_.isLeaf(c) && sourceHead_[c] != -1) work.push_back(c);
  }
}

template <int D>
bool TreeControlSpace<D>::initialSplitNeeded(int leaf) const {
  for (int s = sourceHead_[leaf]; s != -1; s = sources_[s].next) {
    const PointSource& a = sources_[s];
    // a checked source was short enough in an ancestor, hence in this smaller leaf, unless
    // the cached M_p it is measured with changed
    if ((!a.checked || hasAux_) && maxEdgeMetricLength(leaf, a.m, auxAt(a.x)) > lMax_) return true;
    if (a.checked) continue;
    for (int r = sourceHead_[leaf]; r != -1; r = sources_[r].next)
      if (r != s && metricDifference(a.m, sources_[r].m) > epsDelta_) return true;
  }
  return false;
}

template <int D>
void TreeControlSpace<D>::markChecked(int leaf) {
  for (int s = sourceHead_[leaf]; s != -1; s = sources_[s].next) sources_[s].checked = true;
}

template <int D>
void TreeControlSpace<D>::insertUpdate(const Vec& x, const Metric<D>& m) {
  Vec local;
  int leaf = tree_.locate(x, local);
  const Metric<D> current = metricIn(leaf, local);
  if (metricDifference(m, current) < epsDelta_) return;             // step 2
  if (metricDifference(intersect(m, current), current) < epsDelta_) return;  // steps 3–4
  // Step 5: split while the leaf is long in the new metric (balanced splits).
  while (maxEdgeMetricLength(leaf, m, auxIn(leaf, local)) > lMax_ && splitLeaf(leaf))
    leaf = tree_.locate(x, local);
  for (int v : tree_.corners(leaf)) intersectVertex(v, m);
  if (tree_.hasExtras(leaf))
    for (int s = 0; s < Tree::kExtraSlots; ++s)
      if (tree_.extra(leaf, s) != Tree::kNone) intersectVertex(tree_.extra(leaf, s), m);
}

template <int D>
void TreeControlSpace<D>::setContinuous(const MetricFn& source) {
  const bool had = valued_;
  for (int v = 0; v < tree_.vertexCount(); ++v) {
    const Metric<D> s = source(tree_.point(v));
    setVertex(v, had ? intersect(metric_[v], s) : s);
  }
  valued_ = true;
  ++revision_;
  std::vector<int> work = tree_.leaves();
  continuous_ = &source;
  continuousExact_ = !had;
  newLeaves_ = &work;
  try {
    while (!work.empty()) {
      const int n = work.back();
      work.pop_back();
      if (!tree_.isLeaf(n)) continue;
      // The source is compared with the field at the leaf's centre and at the centres of
      // its would-be children: the centre alone misses a feature that vanishes there (the
      // curvature of SURF1, eq. A.3, is zero at the centre of its domain and the whole patch
      // stayed at h_max).
      bool split = false;
      for (int k = -1; k < (1 << D) && !split; ++k) {
        Vec local = Vec::Constant(0.5);
        if (k >= 0)
          for (int d = 0; d < D; ++d) local[d] = (k >> d) & 1 ? 0.75 : 0.25;
        const Vec at = tree_.nodeLo(n) + local.cwiseProduct(tree_.nodeSize(n));
        const Metric<D> exact = source(at);
        // Every vertex of the leaf carries exactly this metric: the field is a convex
        // combination of equal tensors, equal to it to rounding (difference ~1e-16, far
        // below ε_δ) — the test below would pass; skipped (a uniform source: most leaves).
        if (continuousExact_ && leafCarries(n, exact)) continue;
        const Metric<D> interpolated = metricIn(n, local);
        // Fresh: the field must reproduce the source. Valued: only where the source asks for
        // a finer metric than the field gives (where earlier sources were finer, splitting
        // could never bring the two closer).
        const Metric<D> target = continuousExact_ ? exact : intersect(interpolated, exact);
        if (metricDifference(target, interpolated) <= epsDelta_) continue;
        if (belowResolution(n, exact)) continue;
        split = true;
      }
      if (split) splitLeaf(n);
    }
  } catch (...) {
    continuous_ = nullptr;
    newLeaves_ = nullptr;
    throw;
  }
  continuous_ = nullptr;
  newLeaves_ = nullptr;
}

template <int D>
bool TreeControlSpace<D>::leafCarries(int leaf, const Metric<D>& m) const {
  for (const int v : tree_.corners(leaf))
    if (metric_[v].matrix() != m.matrix()) return false;
  if (tree_.hasExtras(leaf))
    for (int s = 0; s < Tree::kExtraSlots; ++s) {
      const int v = tree_.extra(leaf, s);
      if (v != Tree::kNone && metric_[v].matrix() != m.matrix()) return false;
    }
  return true;
}

template <int D>
void TreeControlSpace<D>::adaptAux(const MatFn& exact) {
  aux_.resize(tree_.vertexCount());
  for (int v = 0; v < tree_.vertexCount(); ++v) aux_[v] = exact(tree_.point(v));
  hasAux_ = true;
  auxExact_ = exact;
  ++revision_;
  std::vector<int> work = tree_.leaves();
  newLeaves_ = &work;
  try {
    while (!work.empty()) {
      const int n = work.back();
      work.pop_back();
      if (!tree_.isLeaf(n)) continue;
      const Vec half = Vec::Constant(0.5);
      const Mat centre = exact(tree_.nodeCentre(n));
      double worst = tensorDifference<D>(centre, auxIn(n, half));
      for (int v : tree_.corners(n)) worst = std::max(worst, tensorDifference<D>(centre, aux_[v]));
      if (worst <= epsDelta_) continue;
      if (valued_ && belowResolution(n, metricIn(n, half))) continue;
      splitLeaf(n);
    }
  } catch (...) {
    newLeaves_ = nullptr;
    throw;
  }
  newLeaves_ = nullptr;
}

template class TreeControlSpace<2>;
template class TreeControlSpace<3>;

}  // namespace aniso
