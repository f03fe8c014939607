#pragma once
// Floating-point expansion arithmetic (internal to mesher/predicates).
//
// An expansion is a sum of doubles x_0 + x_1 + ... + x_{n-1}, stored in increasing order of
// magnitude, whose components are nonoverlapping: the value is represented exactly, and the
// sign of the sum is the sign of the last (largest) component. The algorithms follow the
// published ideas of Priest (1991) and Shewchuk ("Adaptive precision floating-point
// arithmetic and fast robust geometric predicates", 1997): error-free transformations
// (two-sum, two-product with a fused multiply-add), expansion sum by merging the components
// by magnitude and accumulating with two-sum, and scaling by a double, both with zero
// elimination (zero components are dropped; the empty expansion is the value 0).
//
// Exactness holds while no operation overflows and no product error term underflows; the
// callers in Predicates.cpp guarantee this by restricting the magnitude range of the inputs
// (and rescaling them by powers of two) before they use these routines.
// Requires IEEE 754 binary64 with round-to-nearest-even and no floating-point contraction
// of the expressions below (ISO C++ mode: GCC does not contract across statements then).
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace aniso::predicates::detail {

/// x + y = a + b exactly, x = fl(a + b).
inline void twoSum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}
/// x + y = a + b exactly, x = fl(a + b); requires |a| >= |b| (or a == 0).
inline void fastTwoSum(double a, double b, double& x, double& y) {
  x = a + b;
  y = b - (x - a);
}
/// x + y = a − b exactly.
inline void twoDiff(double a, double b, double& x, double& y) { twoSum(a, -b, x, y); }
/// x + y = a · b exactly (barring underflow of y), x = fl(a · b).
inline void twoProduct(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

/// Read-only view of an expansion: n components at v, increasing magnitude, no zeros.
struct Ex {
  const double* v = nullptr;
  int n = 0;
  /// −1, 0 or +1: the sign of the exact value.
  int sign() const { return n == 0 ? 0 : (v[n - 1] > 0 ? 1 : -1); }
  /// The largest component: an approximation of the value (within a factor of 2).
  double estimate() const { return n == 0 ? 0.0 : v[n - 1]; }
};

/// Bump allocator for expansion buffers: a fixed stack block, then heap blocks. Lives for
/// one predicate evaluation; nothing is freed individually.
class Arena {
 public:
  double* get(std::size_t n) {
    if (used_ + n <= kLocal) {
      double* p = local_ + used_;
      used_ += n;
      return p;
    }
    heap_.push_back(std::make_unique<double[]>(n));
    return heap_.back().get();
  }

 private:
  static constexpr std::size_t kLocal = 3072;
  double local_[kLocal];
  std::size_t used_ = 0;
  std::vector<std::unique_ptr<double[]>> heap_;
};

/// h = e + f (zero-eliminating merge sum). h must hold e.n + f.n doubles and not alias.
/// Returns the number of components written.
inline int sumInto(Ex e, Ex f, double* h) {
  int i = 0, j = 0, k = 0;
  const int total = e.n + f.n;
  if (total == 0) return 0;
  // Next component in increasing magnitude from the two sorted inputs.
  auto next = [&]() -> double {
    if (j >= f.n || (i < e.n && std::fabs(e.v[i]) <= std::fabs(f.v[j]))) return e.v[i++];
    return f.v[j++];
  };
  double q = next();
  for (int t = 1; t < total; ++t) {
    double x, y;
    twoSum(q, next(), x, y);
    if (y != 0.0) h[k++] = y;
    q = x;
  }
  if (q != 0.0) h[k++] = q;
  return k;
}

/// h = e · b (zero-eliminating scale). h must hold 2·e.n doubles and not alias e.
inline int scaleInto(Ex e, double b, double* h) {
  if (e.n == 0 || b == 0.0) return 0;
  int k = 0;
  double q, hh;
  twoProduct(e.v[0], b, q, hh);
  if (hh != 0.0) h[k++] = hh;
  for (int i = 1; i < e.n; ++i) {
    double p1, p0, s;
    twoProduct(e.v[i], b, p1, p0);
    twoSum(q, p0, s, hh);
    if (hh != 0.0) h[k++] = hh;
    fastTwoSum(p1, s, q, hh);
    if (hh != 0.0) h[k++] = hh;
  }
  if (q != 0.0) h[k++] = q;
  return k;
}

inline Ex sum(Arena& a, Ex e, Ex f) {
  double* h = a.get(static_cast<std::size_t>(e.n + f.n));
  return {h, sumInto(e, f, h)};
}
inline Ex negate(Arena& a, Ex e) {
  double* h = a.get(static_cast<std::size_t>(e.n));
  for (int i = 0; i < e.n; ++i) h[i] = -e.v[i];
  return {h, e.n};
}
inline Ex diff(Arena& a, Ex e, Ex f) { return sum(a, e, negate(a, f)); }
inline Ex scale(Arena& a, Ex e, double b) {
  double* h = a.get(2 * static_cast<std::size_t>(e.n));
  return {h, scaleInto(e, b, h)};
}
/// e · f: the longer operand is scaled by each component of the shorter one and the partial
/// products are accumulated in two ping-pong buffers.
inline Ex product(Arena& a, Ex e, Ex f) {
  if (e.n < f.n) std::swap(e, f);
  if (f.n == 0 || e.n == 0) return {};
  if (f.n == 1) return scale(a, e, f.v[0]);
  const std::size_t cap = 2 * static_cast<std::size_t>(e.n) * static_cast<std::size_t>(f.n);
  double* bufA = a.get(cap);
  double* bufB = a.get(cap);
  double* part = a.get(2 * static_cast<std::size_t>(e.n));
  Ex acc{bufA, scaleInto(e, f.v[0], bufA)};
  for (int j = 1; j < f.n; ++j) {
    const Ex p{part, scaleInto(e, f.v[j], part)};
    double* out = (acc.v == bufA) ? bufB : bufA;
    acc = {out, sumInto(acc, p, out)};
  }
  return acc;
}
/// The exact difference a − b as an expansion of at most two components.
inline Ex exactDiff(Arena& ar, double a, double b) {
  double* h = ar.get(2);
  double x, y;
  twoDiff(a, b, x, y);
  int k = 0;
  if (y != 0.0) h[k++] = y;
  if (x != 0.0) h[k++] = x;
  return {h, k};
}

}  // namespace aniso::predicates::detail
