#pragma once
// SeedQuadtree — the seeding quadtree of thesis sec. 4.4.1: a good starting element for
// the directed walk of point location (PointLocation.h). Following the thesis' choice
// (Fig. 4.7–4.8: "the set of vertices … as representative points, with quadtree leaf
// threshold value of 300"), the representative points are the triangulation's vertices;
// a vertex leads to a triangle through Triangulation2d::vertexTriangle, which the
// operators keep up to date, so no triangle has to be re-sifted after a modification.
//
// A leaf holds at most `leafThreshold` points (more only at maxDepth); an overfull leaf
// is split into four. A query descends to the leaf containing the query point (or, when
// it is empty, to the nearest non-empty leaf of the closest ancestor) and returns the
// nearest of at most `sampleSize` of its points, the most recent first (with a stride
// over the older ones), among those accepted by the caller.
//
// Points outside the root box are accepted (they go to the boundary leaves).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/delaunay/Handles.h"

namespace aniso::del2d {

struct SeedQuadtreeOptions {
  std::uint32_t leafThreshold = 300;  ///< thesis sec. 4.4.1 (≥ 1)
  std::uint32_t sampleSize = 16;      ///< points compared per query (≥ 1)
  std::uint32_t maxDepth = 24;        ///< no split below this depth (coincident points)
};

class SeedQuadtree {
 public:
  SeedQuadtree() = default;
  /// Throws MeshingError when the box is empty or an option is 0.
  SeedQuadtree(const Box2& box, const SeedQuadtreeOptions& options);

  void insert(VertexId v, const Vec2& p);
  /// Nearest sampled point of the leaf of p (see above) with accept(v) true, or an invalid
  /// id when the tree is empty or no sampled point is accepted.
  template <class Accept>
  VertexId nearestSample(const Vec2& p, Accept&& accept) const;

  std::size_t size() const { return nodes_.empty() ? 0 : nodes_[0].count; }
  std::size_t numLeaves() const;
  std::uint32_t depth() const { return maxDepthReached_; }
  void clear();

 private:
  struct Node {
    Vec2 lo, hi;
    std::uint32_t firstChild = kNone;  ///< four consecutive nodes, or kNone for a leaf
    std::uint32_t bucket = kNone;      ///< leaf: index into buckets_
    std::uint32_t count = 0;           ///< points in the subtree
    std::uint32_t depth = 0;
  };
  struct Entry {
    double x, y;
    std::uint32_t v;
  };
  static int childOf(const Node& n, double x, double y) {
    const double cx = 0.5 * (n.lo.x() + n.hi.x()), cy = 0.5 * (n.lo.y() + n.hi.y());
    return (x >= cx ? 1 : 0) | (y >= cy ? 2 : 0);
  }
  void split(std::uint32_t node);
  /// The leaf to sample for p (non-empty unless the tree is empty).
  std::uint32_t sampleLeaf(double x, double y) const;

  SeedQuadtreeOptions options_;
  std::vector<Node> nodes_;
  std::vector<std::vector<Entry>> buckets_;
  std::uint32_t maxDepthReached_ = 0;
};

template <class Accept>
VertexId SeedQuadtree::nearestSample(const Vec2& p, Accept&& accept) const {
  if (size() == 0) return VertexId();
  const std::vector<Entry>& b = buckets_[nodes_[sampleLeaf(p.x(), p.y())].bucket];
  const std::size_t n = b.size();
  const std::size_t want = options_.sampleSize;
  const std::size_t stride = n > want ? n / want : 1;
  VertexId best;
  double bestD = 0.0;
  std::size_t taken = 0;
  for (std::size_t k = n; k > 0 && taken < want; k = k > stride ? k - stride : 0, ++taken) {
    const Entry& e = b[k - 1];
    const double dx = e.x - p.x(), dy = e.y - p.y();
    const double d = dx * dx + dy * dy;
    if ((!best.valid() || d < bestD) && accept(VertexId(e.v))) {
      best = VertexId(e.v);
      bestD = d;
    }
  }
  return best;
}

}  // namespace aniso::del2d
