#pragma once
// Basic geometric value types shared by every part of the library.
// Eigen fixed-size types: stack-allocated, no alignment pitfalls for 2- and 3-vectors.
#include <Eigen/Core>

namespace aniso {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat2 = Eigen::Matrix2d;
using Mat3 = Eigen::Matrix3d;

/// Axis-aligned box in 2D or 3D. Empty when min > max in any coordinate.
template <int D>
struct Box {
  using V = Eigen::Matrix<double, D, 1>;
  V lo = V::Constant(1e300);
  V hi = V::Constant(-1e300);
  bool empty() const { return (lo.array() > hi.array()).any(); }
  void add(const V& p) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
  void add(const Box& b) { if (!b.empty()) { add(b.lo); add(b.hi); } }
  V size() const { return empty() ? V::Zero() : V(hi - lo); }
  double diagonal() const { return size().norm(); }
  bool contains(const V& p, double tol = 0) const {
    return ((p.array() >= lo.array() - tol) && (p.array() <= hi.array() + tol)).all();
  }
};
using Box2 = Box<2>;
using Box3 = Box<3>;

}  // namespace aniso
