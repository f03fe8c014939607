#pragma once
// TriangleTree — the closest point of a set of triangles (a solid's boundary mesh) to a query
// point, within a search radius: a bounding-volume hierarchy (the triangles split at the
// median of their centroids along the longest axis, kLeafTriangles per leaf) searched branch
// and bound (a subtree is skipped when its box is farther than the best point so far).
// For VolumeMetricSpace's grading of M_v from the surface (VolumeControlSpace.h).
// With a near radius R, also a uniform grid of cells (R/2 wide, coarser beyond kMaxNearCells)
// flagging those within R of a triangle (each triangle's box grown by R): beyond(x, d) then
// answers most queries far from the surface without the tree (docs/measurements.md).
// Read-only after construction: queries are thread-safe. Deterministic (ties keep the first
// triangle found in a fixed traversal order).
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

/// Closest point of the triangle (a, b, c) to p (Voronoi regions of the vertices, edges and
/// face; Ericson, Real-Time Collision Detection, 5.1.5). Exactly a, b or c when p is one.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

class TriangleTree {
 public:
  /// The triangles are point index triples into `points` (the points they use are copied).
  /// `nearRadius` > 0: the grid of beyond() for distances up to it.
  TriangleTree(std::span<const Vec3> points, std::span<const std::array<int, 3>> triangles, double nearRadius = 0);
  /// True when x is certainly farther than `distance` from every triangle (the grid's cell of
  /// x is not within the near radius of any, and distance ≤ that radius); false when unknown.
  bool beyond(const Vec3& x, double distance) const;
  /// The closest point of the triangles to x when one is within maxDistance (Euclidean):
  /// true and `out` set; false otherwise (or with no triangles).
  bool closest(const Vec3& x, double maxDistance, Vec3& out) const;
  std::size_t size() const { return tris_.size(); }

 private:
  struct Node {
    Box3 box;
    std::uint32_t first = 0, count = 0;  ///< leaf: tris_[first, first + count)
    std::int32_t left = -1, right = -1;  ///< inner node: children
  };
  /// The subtree over the positions [first, first + count) of perm (position -> triangle);
  /// order is scratch.
  std::int32_t build(std::uint32_t first, std::uint32_t count, const std::vector<Vec3>& centroids,
                     std::vector<std::uint32_t>& perm, std::vector<std::uint32_t>& order);
  void buildNearGrid(double radius);
  bool cellOf(const Vec3& x, std::size_t& cell) const;

  std::vector<Vec3> points_;                     ///< the points the triangles use
  std::vector<std::array<std::uint32_t, 3>> tris_;  ///< into points_, in the tree's leaf order
  std::vector<Node> nodes_;
  double nearRadius_ = 0, cell_ = 0;
  Vec3 origin_ = Vec3::Zero();
  std::array<std::size_t, 3> cells_{0, 0, 0};
  std::vector<std::uint64_t> near_;  ///< one bit per cell
};

/// Cells of TriangleTree's near grid at most (coarser cells beyond: still exact, less pruning).
inline constexpr std::size_t kMaxNearCells = std::size_t{1} << 23;  // 1 MB of bits

}  // namespace aniso
