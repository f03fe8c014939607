// TreeControlSpace<D>: operations over all control vertices — initialization from pending
// point sources with extrapolation (3.3.1 steps 2–3), gradation smoothing (3.3.4),
// visiting, export and validation.
#include <algorithm>
#include <cmath>
#include <string>

#include "mesher/control/ControlSpaceGridTensors.h"
#include "mesher/control/TreeControlSpace.h"
#include "mesher/core/Error.h"
#include "mesher/metric/MetricGradation.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/metric/MetricInterpolation.h"
#include "mesher/metric/SymmetricEigen.h"

namespace aniso {
namespace {

/// Sweeps of the gradation smoothing before it is reported as not converging.
constexpr int kMaxGradationSweeps = 100000;
/// Relative change of an eigenvalue that counts as a change of a smoothed metric.
constexpr double kGradationChangeTolerance = 1e-9;
/// A pending source this close to a vertex (relative to the leaf size) is taken as is.
constexpr double kCoincidentRelative = 1e-9;

}  // namespace

// Sorted by (a, b) with the deepest level first among equal pairs, then deduplicated: as a
// bucket sort by a (counting sort), each bucket (a dozen edges) sorted by (b, level
// descending) — the order of one global sort, without its cost (half of the volume's
// gradation smoothing on the cube at h 0.02).
template <int D>
std::vector<typename TreeControlSpace<D>::Edge> TreeControlSpace<D>::edges() const {
  const std::vector<int> leaves = tree_.leaves();
  const int nv = tree_.vertexCount();
  std::vector<int> start(static_cast<std::size_t>(nv) + 1, 0);
  auto forEachLeafEdge = [&](auto&& f) {
    for (int leaf : leaves) {
      const auto& c = tree_.corners(leaf);
      for (int k = 0; k < D; ++k)
        for (int i = 0; i < Tree::kCorners; ++i) {
          if ((i >> k) & 1) continue;
          const int a = c[i], b = c[i | (1 << k)];
          f(Edge{std::min(a, b), std::max(a, b), tree_.level(leaf)});
        }
    }
  };
  forEachLeafEdge([&](const Edge& x) { ++start[x.a + 1]; });
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<Edge> all(static_cast<std::size_t>(start[nv]));
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    forEachLeafEdge([&](const Edge& x) { all[fill[x.a]++] = x; });
  }
  auto before = [](const Edge& x, const Edge& y) { return x.b != y.b ? x.b < y.b : x.level > y.level; };
  std::vector<Edge> e;
  e.reserve(all.size() / 2);
  for (int v = 0; v < nv; ++v) {
    const auto first = all.begin() + start[v], last = all.begin() + start[v + 1];
    std::sort(first, last, before);
    for (auto it = first; it != last; ++it)
      if (it == first || it->b != (it - 1)->b) e.push_back(*it);
  }
  return e;
}

template <int D>
void TreeControlSpace<D>::initializeVertices() {
  if (pending_ == 0) {
    if (valued_) return;
    throw MeshingError("control space: no metric source to initialize the control vertices from");
  }
  const int nv = tree_.vertexCount();
  std::vector<std::uint8_t> known(nv, valued_ ? 1 : 0);
  std::vector<Metric<D>> average(nv);
  std::vector<std::uint8_t> hasAverage(nv, 0);
  for (int v = 0; v < nv; ++v) {
    std::array<int, Tree::kCorners> around;
    const int count = tree_.leavesAround(v, around);
    const Vec p = tree_.point(v);
    MetricBlend<D> weighted, coincident;
    for (int i = 0; i < count; ++i) {
      const double tiny = kCoincidentRelative * tree_.nodeSize(around[i]).norm();
      for (int s = sourceHead_[around[i]]; s != -1; s = sources_[s].next) {
        const double d = (sources_[s].x - p).norm();
        if (d <= tiny)
          coincident.add(sources_[s].m, 1);
        else
          weighted.add(sources_[s].m, 1 / (d * d));
      }
    }
    if (!coincident.empty())
      average[v] = coincident.result();
    else if (!weighted.empty())
      average[v] = weighted.result();
    else
      continue;
    hasAverage[v] = 1;
  }
  for (int v = 0; v < nv; ++v) {
    if (!hasAverage[v]) continue;
    setVertex(v, valued_ ? intersect(metric_[v], average[v]) : average[v]);
    known[v] = 1;
  }
  if (!valued_) extrapolate(known);
  std::vector<PointSource>().swap(sources_);  // the pending sources' memory too (with the meshes)
  std::fill(sourceHead_.begin(), sourceHead_.end(), -1);
  pending_ = 0;
  valued_ = true;
  ++revision_;
}

template <int D>
void TreeControlSpace<D>::extrapolate(std::vector<std::uint8_t>& known) {
  // Vertex adjacency along leaf edges (CSR).
  const int nv = tree_.vertexCount();
  const std::vector<Edge> e = edges();
  std::vector<int> start(nv + 1, 0), adj(2 * e.size());
  for (const Edge& x : e) {
    ++start[x.a + 1];
    ++start[x.b + 1];
  }
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const Edge& x : e) {
    adj[fill[x.a]++] = x.b;
    adj[fill[x.b]++] = x.a;
  }
  // Layers: every unknown vertex next to a known one takes the inverse-distance weighted
  // average of its known neighbours; the layer then becomes known.
  std::vector<int> front;
  for (;;) {
    front.clear();
    for (int v = 0; v < nv; ++v) {
      if (known[v]) continue;
      for (int j = start[v]; j < start[v + 1]; ++j)
        if (known[adj[j]]) {
          front.push_back(v);
          break;
        }
    }
    if (front.empty()) break;
    for (int v : front) {
      MetricBlend<D> b;
      for (int j = start[v]; j < start[v + 1]; ++j)
        if (known[adj[j]]) b.add(metric_[adj[j]], 1 / (tree_.point(adj[j]) - tree_.point(v)).norm());
      setVertex(v, b.result());
    }
    for (int v : front) known[v] = 1;
  }
  if (std::find(known.begin(), known.end(), 0) != known.end())
    throw MeshingError("control space: extrapolation did not reach every control vertex");
}

template <int D>
int TreeControlSpace<D>::smoothGradation(double gamma) {
  if (!valued_) failFresh(tree_.nodeCentre(0));
  gradationSlopeLimit(gamma);  // throws for an invalid γ_M
  const GradationRule rule{gamma, 0.0, kGradationChangeTolerance};
  // Deepest leaves first, stable (counting sort by level).
  std::vector<Edge> up;
  {
    const std::vector<Edge> e = edges();
    std::vector<std::size_t> at(Tree::kResolution + 2, 0);
    for (const Edge& x : e) ++at[Tree::kResolution - x.level + 1];
    for (std::size_t k = 1; k < at.size(); ++k) at[k] += at[k - 1];
    up.resize(e.size());
    for (const Edge& x : e) up[at[Tree::kResolution - x.level]++] = x;
  }
  std::vector<Edge> down(up.rbegin(), up.rend());
  // stamp[v]: last sweep in which v changed. A pair is revisited only when an endpoint
  // changed in the previous or the current sweep.
  std::vector<int> stamp(tree_.vertexCount(), 0);
  // Cheap exact test that a pair is already graded (most are): with the metric tensors
  // T = M² and s the factor of eq. 2.30, smoothGradation changes nothing when s² T_a − T_b
  // and s² T_b − T_a are positive definite (Sylvester's criterion), because then each
  // relaxed metric (tensor T/s²) lies inside the other one.
  std::vector<Mat> tensor(tree_.vertexCount());
  for (int v = 0; v < tree_.vertexCount(); ++v) tensor[v] = metric_[v].tensor();
  for (int sweep = 1; sweep <= kMaxGradationSweeps; ++sweep) {
    bool changed = false;
    for (const Edge& x : (sweep % 2 ? up : down)) {
      if (sweep > 1 && stamp[x.a] < sweep - 1 && stamp[x.b] < sweep - 1) continue;
      Vec d = tree_.point(x.b) - tree_.point(x.a);
      if (hasAux_) d = (0.5 * (aux_[x.a] + aux_[x.b]) * d).eval();  // M_p at the midpoint (eq. 2.13)
      const double dR = d.norm();
      if (dR > 0) {
        const double f = gradationFactor(metric_[x.a].lengthAlong(d), metric_[x.b].lengthAlong(d), dR, gamma);
        const double f2 = f * f;
        if (isSymmetricPositiveDefinite(Mat(f2 * tensor[x.a] - tensor[x.b])) &&
            isSymmetricPositiveDefinite(Mat(f2 * tensor[x.b] - tensor[x.a])))
          continue;
      }
      if (aniso::smoothGradation<D>(metric_[x.a], metric_[x.b], d, rule)) {
        stamp[x.a] = stamp[x.b] = sweep;
        tensor[x.a] = metric_[x.a].tensor();
        tensor[x.b] = metric_[x.b].tensor();
        changed = true;
      }
    }
    if (!changed) {
      for (int v = 0; v < tree_.vertexCount(); ++v)
        if (stamp[v] > 0) length_[v] = metric_[v].inverseMatrix();
      ++revision_;
      return sweep;
    }
  }
  throw MeshingError("control space: gradation smoothing did not converge in " +
                     std::to_string(kMaxGradationSweeps) + " sweeps");
}

template <int D>
void TreeControlSpace<D>::forEachVertex(const VertexVisitor& visit) const {
  if (!valued_) return;
  for (int v = 0; v < tree_.vertexCount(); ++v) visit(tree_.point(v), metric_[v]);
}

template <int D>
void TreeControlSpace<D>::modifyVertices(const VertexModifier& modify) {
  if (!valued_) return;
  for (int v = 0; v < tree_.vertexCount(); ++v) {
    Metric<D> m = metric_[v];
    if (modify(tree_.point(v), m)) setVertex(v, m);
  }
  ++revision_;
}

template <int D>
ControlSpaceGrid TreeControlSpace<D>::grid() const {
  ControlSpaceGrid g;
  g.dim = D;
  g.cellSize = Tree::kCorners;
  const int nv = tree_.vertexCount();
  g.points.resize(nv);
  for (int v = 0; v < nv; ++v) {
    g.points[v].setZero();
    g.points[v].template head<D>() = tree_.point(v);
  }
  // VTK_QUAD / VTK_HEXAHEDRON order from the (bit k = axis k) corner numbering.
  static constexpr int kVtk[8] = {0, 1, 3, 2, 4, 5, 7, 6};
  for (int leaf : tree_.leaves()) {
    for (int i = 0; i < Tree::kCorners; ++i) g.cells.push_back(tree_.corners(leaf)[kVtk[i]]);
    g.cellLevel.push_back(tree_.level(leaf));
  }
  if (valued_) setGridTensors<D>(g, metric_);
  if (hasAux_) setGridParameterization<D>(g, aux_);
  return g;
}

template <int D>
void TreeControlSpace<D>::validate() const {
  tree_.validate();
  const std::string where = D == 2 ? "quadtree control space invalid: " : "octree control space invalid: ";
  const int nv = tree_.vertexCount();
  if (int(metric_.size()) != nv || int(length_.size()) != nv || (hasAux_ && int(aux_.size()) != nv))
    throw MeshingError(where + "per-vertex arrays do not match the vertex count");
  for (int v = 0; v < nv && valued_; ++v) {
    const Mat& m = metric_[v].matrix();
    if (!isSymmetricPositiveDefinite(m))
      throw MeshingError(where + "metric of vertex " + std::to_string(v) + " is not SPD");
    if (!((length_[v] * m - Mat::Identity()).norm() < 1e-8))
      throw MeshingError(where + "stored inverse of vertex " + std::to_string(v) + " is stale");
  }
  for (int v = 0; v < nv && hasAux_; ++v)
    if (!isSymmetricPositiveDefinite(aux_[v]))
      throw MeshingError(where + "parameterization tensor of vertex " + std::to_string(v) + " is not SPD");
  std::size_t counted = 0;
  for (int leaf : tree_.leaves())
    for (int s = sourceHead_[leaf]; s != -1; s = sources_[s].next, ++counted)
      if (tree_.locate(sources_[s].x) != leaf)
        throw MeshingError(where + "pending source " + std::to_string(s) + " is not in its leaf");
  if (counted != pending_) throw MeshingError(where + "pending sources are lost or misplaced");
}

#define ANISO_TREE_CS_MEMBERS(D)                                                                   \
  template std::vector<TreeControlSpace<D>::Edge> TreeControlSpace<D>::edges() const;              \
  template void TreeControlSpace<D>::initializeVertices();                                         \
  template void TreeControlSpace<D>::extrapolate(std::vector<std::uint8_t>&);                      \
  template int TreeControlSpace<D>::smoothGradation(double);                                       \
  template void TreeControlSpace<D>::forEachVertex(const VertexVisitor&) const;                    \
  template void TreeControlSpace<D>::modifyVertices(const VertexModifier&);                        \
  template ControlSpaceGrid TreeControlSpace<D>::grid() const;                                     \
  template void TreeControlSpace<D>::validate() const;
ANISO_TREE_CS_MEMBERS(2)
ANISO_TREE_CS_MEMBERS(3)
#undef ANISO_TREE_CS_MEMBERS

}  // namespace aniso
