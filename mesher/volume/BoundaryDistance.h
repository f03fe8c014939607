#pragma once
// TriangleTree — the closest point of a set of triangles (a solid's boundary mesh) to a query
// point, within a search radius: a bounding-volume hierarchy (the triangles split at the
// median of their centroids along the longest axis, kLeafTriangles per leaf) searched branch
// and bound (a subtree is skipped when its box is farther than the best point so far).
// For VolumeMetricSpace's grading of M_v from the surface (VolumeControlSpace.h).
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
  /// The triangles are point index triples into `points` (copied).
  TriangleTree(std::span<const Vec3> points, std::span<const std::array<int, 3>> triangles);
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
  std::int32_t build(std::uint32_t first, std::uint32_t count, std::vector<Vec3>& centroids);

  std::vector<std::array<Vec3, 3>> tris_;
  std::vector<Node> nodes_;
};

}  // namespace aniso
