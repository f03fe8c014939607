#pragma once
// PlaneTransform — the constant linear transformation M of the metric-space tests of the
// 2D kernel (P^M = M P, thesis sec. 2.2 / 4.2): applies M to points and evaluates the
// in-circle criterion on the transformed doubles with the exact predicate, correcting
// the sign when M reverses orientation (det M < 0). The transformed coordinates are
// rounded doubles; every test of the kernel uses this one routine, so insertion, flips
// and validation agree exactly on them. The identity is detected and skips the products.
#include <cmath>

#include "mesher/core/Types.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::del2d {

class PlaneTransform {
 public:
  explicit PlaneTransform(const Mat2& m = Mat2::Identity())
      : m_(m), identity_(m == Mat2::Identity()) {
    const double det = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
    orientation_ = (!m.allFinite() || det == 0 || !std::isfinite(det)) ? 0 : (det > 0 ? 1 : -1);
  }
  const Mat2& matrix() const { return m_; }
  bool isIdentity() const { return identity_; }
  /// +1 or −1: sign of det M; 0 when M is singular or not finite (unusable).
  int orientation() const { return orientation_; }
  Vec2 apply(const Vec2& p) const { return identity_ ? p : Vec2(m_ * p); }
  /// > 0 iff M p lies strictly inside the circle through M a, M b, M c, for a, b, c
  /// counter-clockwise in the untransformed plane; 0 when cocircular. `mp` = apply(p).
  double inCircle(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& mp) const {
    if (identity_) return predicates::incircle(a.data(), b.data(), c.data(), mp.data());
    const Vec2 ma = m_ * a, mb = m_ * b, mc = m_ * c;
    return orientation_ * predicates::incircle(ma.data(), mb.data(), mc.data(), mp.data());
  }

 private:
  Mat2 m_;
  bool identity_;
  int orientation_;
};

}  // namespace aniso::del2d
