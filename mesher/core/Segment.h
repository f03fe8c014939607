#pragma once
// Closest point on a segment, in 2D or 3D: the one implementation the geometry, sizing and
// meshing code share.
#include <algorithm>

#include <Eigen/Core>

namespace aniso {

/// Parameter t ∈ [0, 1] of the point of segment [a, b] nearest to x (0 for a == b).
template <class V>
double closestSegmentParameter(const V& x, const V& a, const V& b) {
  const V ab = b - a;
  const double l2 = ab.squaredNorm();
  return l2 > 0 ? std::clamp((x - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
}

/// The point of segment [a, b] nearest to x.
template <class V>
V closestPointOnSegment(const V& x, const V& a, const V& b) {
  return a + closestSegmentParameter(x, a, b) * (b - a);
}

/// Euclidean distance from x to segment [a, b].
template <class V>
double distanceToSegment(const V& x, const V& a, const V& b) {
  return (x - closestPointOnSegment(x, a, b)).norm();
}

}  // namespace aniso
