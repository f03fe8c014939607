#pragma once
// TreeControlSpace<D> — the metric field and the adaptive-control-space procedures of
// sec. 3.3 on a BalancedTree<D>: the engine shared by CSQuadtree2d (D = 2) and CSOctree3d
// (D = 3), which add the dimension-specific interfaces.
//
// Field: every vertex stores a sizing tensor M_s (Metric<D>) and its inverse, the length
// tensor M⁻¹. At a point x of leaf K the length tensor is interpolated with the
// multilinear shape functions of K (eq. 3.1) and inverted, i.e. the n-point form of
// eq. 2.18 (MetricInterpolation.h) with weights N_i(x). Extra (hanging) vertices of K
// (BalancedTree.h) add hierarchical corrections: with φ_g the piecewise-multilinear hat of
// grid node g on K's virtual 3×3(×3) grid,
//     L(x) = Σ_i N_i(x) L_i + Σ_{extras g} φ_g(x) (L_g − L̄_g),
// L̄_g the multilinear value at g (mean of the 2 or 4 corners of its edge / face). The
// result is a convex combination of SPD tensors (so SPD), equals the vertex values at all
// vertices, and is continuous across leaves of different levels because along a shared
// edge / face both sides interpolate the same vertex values. Splitting a leaf never
// changes the field (new vertices get the interpolated value).
// The surface parameterization tensor M_p ("aux", 2D only, sec. 3.2.4 item 1) is cached
// at the vertices the same way and interpolated with the same shape functions, linearly in
// M_p itself.
//
// States: a new tree carries no metric ("fresh"). Discrete sources inserted while fresh
// are kept in per-leaf lists ("setting initial control space", 3.3.1) until
// initializeVertices(); a continuous source gives every vertex a metric at once. Once
// the vertices carry metrics ("valued"), discrete sources use the "updating control
// space" procedure of 3.3.1.
// Parameters (SizingParameters, never globals): ε_M metricDistanceEps (proximity of point
// sources), l_Mmax adaptLengthMax (size sensitivity), ε_δ metricDifferenceEps (metric
// difference). For a 2D tree "metric length" of a parametric vector e means |M_s M_p e|.
// Thread safety: const methods are safe concurrently; the others are not.
#include <cstdint>
#include <functional>
#include <vector>

#include "mesher/control/BalancedTree.h"
#include "mesher/control/ControlSpaceGrid.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/metric/Metric.h"

namespace aniso {

/// Bounds of the structural refinement, beyond the thesis' three rules.
struct TreeLimits {
  /// Deepest level (≤ BalancedTree::kResolution = 24).
  int maxLevel = 24;
  /// The continuous-source and parameterization adaptations (3.3.2, 3.3.3) do not split a
  /// leaf whose edges are all shorter than this in metric units — in the metric of each
  /// of its corners and in the metric at its centre: metric variation far below the
  /// element size does not affect a mesh, and a discontinuous source would otherwise be
  /// refined down to maxLevel.
  double minLeafMetricLength = 0.5;
};

template <int D>
class TreeControlSpace {
 public:
  using Tree = BalancedTree<D>;
  using Vec = typename Tree::Vec;
  using Mat = Eigen::Matrix<double, D, D>;
  using MetricFn = std::function<Metric<D>(const Vec&)>;
  using MatFn = std::function<Mat(const Vec&)>;
  using VertexVisitor = std::function<void(const Vec&, const Metric<D>&)>;
  using VertexModifier = std::function<bool(const Vec&, Metric<D>&)>;

  /// Throws InputError for a bad box, ε_M < 0, ε_δ ≤ 0, l_Mmax ≤ 0 or bad limits.
  TreeControlSpace(const Box<D>& box, const SizingParameters& params, const TreeLimits& limits);

  const Tree& tree() const { return tree_; }
  bool valued() const { return valued_; }
  bool hasAux() const { return hasAux_; }
  std::size_t pendingSources() const { return pending_; }
  /// Changes on every modification (for query caches).
  std::uint64_t revision() const { return revision_; }

  // ---- queries (const, thread-safe) ----
  /// M_s at x (x outside the box: nearest box point). Throws MeshingError while fresh.
  Metric<D> metricAt(const Vec& x) const;
  /// Cached M_p at x; identity when none is cached.
  Mat auxAt(const Vec& x) const;
  /// Both with one point location.
  void sample(const Vec& x, Metric<D>& metric, Mat& aux) const;
  const Metric<D>& vertexMetric(int v) const { return metric_[v]; }
  const Mat& vertexAux(int v) const { return aux_[v]; }
  /// Unique leaf edges as vertex pairs (a < b), with the deepest level of the leaves
  /// that have the edge.
  struct Edge {
    int a, b, level;
  };
  std::vector<Edge> edges() const;

  // ---- operations ----
  /// Point source (sec. 3.3.1): the initial procedure while fresh, the update procedure
  /// when valued.
  void insertDiscrete(const Vec& x, const Metric<D>& m);
  /// Continuous source (sec. 3.3.2): every vertex gets the source's metric (intersected
  /// with its own when valued); then every leaf whose centre value differs by more than
  /// ε_δ from the target — the source when the tree was fresh, min_M(field, source)
  /// otherwise — is split, recursively, down to TreeLimits::minLeafMetricLength.
  void setContinuous(const MetricFn& source);
  /// Steps 2–3 of "setting initial control space" (sec. 3.3.1): weighted average of the
  /// pending sources of the adjacent leaves (inverse squared distance), intersected with
  /// the existing metric when valued, then layer-by-layer extrapolation to vertices with
  /// no source nearby. Throws MeshingError when fresh with no pending source.
  void initializeVertices();
  /// Caches exact M_p at every vertex (and at vertices created later) and splits leaves
  /// until M_p is nearly constant over each (sec. 3.3.3): a leaf is split while
  /// δ_M(M_p(centre), ·) > ε_δ for its interpolated centre value or any corner value.
  void adaptAux(const MatFn& exact);
  /// Global gradation smoothing (sec. 3.3.4) with smoothGradation() of MetricGradation.h
  /// on every leaf edge; alternating sweeps "upwards" (deepest leaves first) and
  /// "downwards" until no pair changes. Returns the number of sweeps. Throws while fresh.
  int smoothGradation(double gamma);
  /// Visits every vertex (only when valued).
  void forEachVertex(const VertexVisitor& visit) const;
  /// Lets `modify` change the metric of every vertex (only when valued); it returns
  /// whether it changed the metric.
  void modifyVertices(const VertexModifier& modify);
  /// Intersects M_s of vertex v with m.
  void intersectVertex(int v, const Metric<D>& m);

  ControlSpaceGrid grid() const;
  /// Tree invariants (BalancedTree::validate), then: vertex metrics SPD and consistent
  /// with the stored inverses, cached M_p SPD, every pending source inside its leaf.
  /// Throws MeshingError naming the first violation.
  void validate() const;

 private:
  /// A pending source. `checked`: the source has passed the metric-difference test against
  /// every source of its leaf (sources only move down the tree, so those stay together);
  /// a new source or one whose metric a proximity merge changed is unchecked.
  struct PointSource {
    Vec x;
    Metric<D> m;
    int next;
    bool checked = false;
  };

  template <class Get>
  Mat blend(int leaf, const Vec& local, const Get& value) const;
  Metric<D> metricIn(int leaf, const Vec& local) const;
  Mat auxIn(int leaf, const Vec& local) const;
  double maxEdgeMetricLength(int leaf, const Metric<D>& m, const Mat& aux) const;
  /// Whether every vertex of the leaf (corners and extras) has exactly the metric m.
  bool leafCarries(int leaf, const Metric<D>& m) const;
  /// TreeLimits::minLeafMetricLength test with the corners' metrics and `centre`.
  bool belowResolution(int leaf, const Metric<D>& centre) const;
  bool splitLeaf(int leaf);
  void onNewVertex(int v, int leaf, const Vec& local);
  void onSplit(int node);
  void setVertex(int v, const Metric<D>& m);
  void insertInitial(const Vec& x, const Metric<D>& m);
  void insertUpdate(const Vec& x, const Metric<D>& m);
  /// Whether a leaf must split by size sensitivity or metric difference (3.3.1). Pairs of
  /// checked sources are not compared again: O(unchecked · sources) per call, not
  /// O(sources²) (thousands of similar sources in one leaf made that cubic overall).
  bool initialSplitNeeded(int leaf) const;
  /// Marks the leaf's sources checked.
  void markChecked(int leaf);
  void extrapolate(std::vector<std::uint8_t>& known);
  [[noreturn]] void failFresh(const Vec& x) const;

  Tree tree_;
  double epsM_, epsDelta_, lMax_;
  TreeLimits limits_;
  bool valued_ = false, hasAux_ = false;
  std::vector<Metric<D>> metric_;  ///< M_s per vertex
  std::vector<Mat> length_;        ///< M_s⁻¹ per vertex
  std::vector<Mat> aux_;           ///< M_p per vertex (when hasAux_)
  MatFn auxExact_;
  std::vector<PointSource> sources_;
  std::vector<int> sourceHead_;  ///< per node, first pending source or −1
  std::size_t pending_ = 0;
  std::uint64_t revision_ = 0;
  // state of the running operation, read by the split hooks
  const MetricFn* continuous_ = nullptr;
  bool continuousExact_ = false;
  std::vector<int>* newLeaves_ = nullptr;
};

extern template class TreeControlSpace<2>;
extern template class TreeControlSpace<3>;

}  // namespace aniso
