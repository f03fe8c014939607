#pragma once
// Circumsphere — the circumsphere of a tetrahedron in floating point, and the cached
// in-sphere filter of the Inserter (identity metric): a tet's centre c̃ and squared radius
// r̃² are computed once, when the tet is made, and the cavity test of a point p becomes the
// sign of D̃ = |p − c̃|² − r̃², certified by an error bound or else left to the exact
// predicates::insphere (sphereSide returns 0). The filter never decides by itself a case
// the bound cannot certify, so every Delaunay decision stays exact.
//
// Error bound (first-order forward analysis, u = 2^−53; constants rounded up generously to
// cover the second-order terms). With U = b − a, V = c − a, W = d − a (rounded), L the
// largest of |U|², |V|², |W|², det = U·(V×W), and the offset õ = N / (2 det),
// N = |U|² V×W + |V|² W×U + |W|² U×V:
//   |N̂_k − N_k| ≤ 14u · 3L²          (evaluation 6u and input rounding 4u on a degree-4
//                                       form whose permanent is ≤ |U|²|V||W| + … ≤ 3L²),
//   |d̂et − det| ≤ 12u · √3 L^{3/2}    (7u + 3u on a degree-3 form, permanent ≤ √3|U||V||W|),
// and, when |d̂et − det| ≤ |d̂et| / 2, the computed offset and centre c̃ = a + õ satisfy
//   |õ − o| ≤ e_o = √3 ((42u L² + 42u m L^{3/2}) / |d̂et| + u m),  m = max_k |õ_k|,
//   |c̃ − c| ≤ E_c = e_o + √3 u max_k |c̃_k|.
// A sphere is certified when E_c ≤ η r̃ (η = 2^−30; evaluated as (E_c |d̂et|)² ≤
// (η |d̂et|)² r̃²) and its magnitudes are far from underflow and overflow (L in
// [2^−200, 2^200], r̃² in [2^−400, 2^400]). For such a sphere and any p, with y = p − c̃
// (rounded),
//   |D̃ − D| ≤ 2 E_c |y| + E_c² + e_o (2 r̃ + e_o) + 3.1u r̃² + 5.1u |y|² + u |D̃|
//           ≤ (3η + 2η² + 5.1u)(r̃² + |y|²) + u |D̃|,
// where D = |p − c|² − R² is the exact power of p (its sign is the exact in-sphere sign:
// negative strictly inside). sphereSide certifies when |D̃| > τ (r̃² + |ỹ|²) with
// τ = 2^−27 (2.6 times that bound), and returns 0 otherwise (also for NaN and infinities).
// sphereFilterAgrees (tests) checks sphereSide against the exact predicate.
#include <cmath>
#include <cstdint>

namespace aniso::del3d {

/// |det| relative to L^{3/2} below which a tet counts as flat (no circumsphere).
inline constexpr double kFlatCircumsphere = 1e-14;

/// The circumcentre of (a, b, c, d) relative to a (the differences b − a, c − a, d − a, their
/// cross products, det and the squared lengths in a fixed order: the refinement's q(K)
/// depends on these exact values). False for a (numerically) flat tet.
bool circumcentreOffset(const double* a, const double* b, const double* c, const double* d, double centre[3]);

/// A tet's circumsphere: centre and squared radius r̃² = |õ|², with the certificate of the
/// cached filter in the sign of radius2.
struct CachedSphere {
  double centre[3];
  /// r̃² (> 0) when the filter may use the sphere; −r̃² (≤ 0) when the centre is too
  /// uncertain for the filter (the radius is still |radius2|); NaN for a flat tet.
  double radius2;
};

/// The circumsphere of (a, b, c, d) (any orientation) with its certificate, written to s
/// (in place: the hot path writes it straight into the cache).
void cachedSphere(const double* a, const double* b, const double* c, const double* d, CachedSphere& s);
inline CachedSphere cachedSphere(const double* a, const double* b, const double* c, const double* d) {
  CachedSphere s;
  cachedSphere(a, b, c, d, s);
  return s;
}

/// Squared circumradius of a cached sphere (NaN for a flat tet).
inline double sphereRadius2(const CachedSphere& s) { return std::fabs(s.radius2); }

/// +1 when p is certified strictly inside the sphere, −1 strictly outside, 0 when the
/// filter cannot certify (the caller evaluates predicates::insphere).
inline int sphereSide(const CachedSphere& s, const double* p) {
  constexpr double kTau = 0x1p-27;
  const double r2 = s.radius2;
  const double yx = p[0] - s.centre[0], yy = p[1] - s.centre[1], yz = p[2] - s.centre[2];
  const double y2 = (yx * yx + yy * yy) + yz * yz;
  const double d = y2 - r2;
  // r2 ≤ 0 or NaN: not certified; an infinite or NaN y2 fails the comparison.
  const bool certain = (r2 > 0) & (std::fabs(d) > kTau * (y2 + r2));
  return certain ? (d < 0 ? 1 : -1) : 0;
}

/// Tests: sphereSide(cachedSphere(a, b, c, d), p) is 0 or the sign of the exact
/// insphere(a, b, c, d, p) taken relative to orient3d(a, b, c, d) (nonzero orientation).
bool sphereFilterAgrees(const double* a, const double* b, const double* c, const double* d, const double* p);

}  // namespace aniso::del3d
