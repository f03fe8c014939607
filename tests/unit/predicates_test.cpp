// Tests of the exact predicates (mesher/predicates/Predicates.h): signs compared with an
// independent exact reference, the classic hard cases (nearly collinear points, exactly
// cocircular/cospherical points, extreme scales, large translations) and antisymmetry.
//
// Reference: every double is an integer times a power of two, so a set of inputs is
// written exactly as integers times one common 2^e0 (BigInt), and the predicate is the
// determinant of the homogeneous matrix (rows (p, 1), (p, |p|², 1)) expanded by Leibniz'
// formula — a different formula and evaluation path from the library's.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "mesher/predicates/ExactInteger.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/predicates/PredicatesExact.h"

using aniso::predicates::incircle;
using aniso::predicates::insphere;
using aniso::predicates::orient2d;
using aniso::predicates::orient3d;
using aniso::predicates::detail::BigInt;
using aniso::predicates::detail::lowExponent;

namespace {

__extension__ typedef __int128 Int128;

int sgn(double v) { return (v > 0) - (v < 0); }

/// Sign of det(m) by Leibniz' formula over all permutations.
int leibnizSign(const std::vector<std::vector<BigInt>>& m) {
  const int n = static_cast<int>(m.size());
  std::vector<int> perm(n);
  std::iota(perm.begin(), perm.end(), 0);
  BigInt total;
  do {
    int inversions = 0;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) inversions += perm[i] > perm[j];
    BigInt term(1);
    for (int i = 0; i < n; ++i) term = term * m[i][perm[i]];
    total = (inversions % 2) ? total - term : total + term;
  } while (std::next_permutation(perm.begin(), perm.end()));
  return total.sign();
}

/// Homogeneous matrix of points (dim coordinates each), optionally lifted, as integers.
int refHomogeneous(const std::vector<const double*>& pts, int dim, bool lifted) {
  int e0 = 0;
  bool any = false;
  for (const double* p : pts)
    for (int k = 0; k < dim; ++k)
      if (p[k] != 0.0) {
        e0 = any ? std::min(e0, lowExponent(p[k])) : lowExponent(p[k]);
        any = true;
      }
  std::vector<std::vector<BigInt>> m;
  for (const double* p : pts) {
    std::vector<BigInt> row;
    BigInt lift;
    for (int k = 0; k < dim; ++k) {
      row.push_back(BigInt::fromDouble(p[k], e0));
      lift = lift + row.back() * row.back();
    }
    if (lifted) row.push_back(lift);
    row.push_back(BigInt(1));
    m.push_back(row);
  }
  return leibnizSign(m);
}

int refOrient2d(const double* a, const double* b, const double* c) {
  return refHomogeneous({a, b, c}, 2, false);
}
int refIncircle(const double* a, const double* b, const double* c, const double* d) {
  return refHomogeneous({a, b, c, d}, 2, true);
}
int refOrient3d(const double* a, const double* b, const double* c, const double* d) {
  return -refHomogeneous({a, b, c, d}, 3, false);
}
int refInsphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
  return -refHomogeneous({a, b, c, d, e}, 3, true);
}

/// Checks all four predicates against the reference on the given points (2D uses the
/// first two coordinates of the first four points).
void expectAllMatch(const std::array<std::array<double, 3>, 5>& q) {
  const double *a = q[0].data(), *b = q[1].data(), *c = q[2].data(), *d = q[3].data(),
               *e = q[4].data();
  double a2[2] = {a[0], a[1]}, b2[2] = {b[0], b[1]}, c2[2] = {c[0], c[1]}, d2[2] = {d[0], d[1]};
  ASSERT_EQ(sgn(orient2d(a2, b2, c2)), refOrient2d(a2, b2, c2));
  ASSERT_EQ(sgn(incircle(a2, b2, c2, d2)), refIncircle(a2, b2, c2, d2));
  ASSERT_EQ(sgn(orient3d(a, b, c, d)), refOrient3d(a, b, c, d));
  ASSERT_EQ(sgn(insphere(a, b, c, d, e)), refInsphere(a, b, c, d, e));
}

using Pts = std::array<std::array<double, 3>, 5>;

template <class F>
Pts makePoints(F gen) {
  Pts q;
  for (auto& p : q)
    for (double& x : p) x = gen();
  return q;
}

}  // namespace

TEST(BigInt, MatchesInt128OnRandomProducts) {
  std::mt19937_64 rng(1);
  for (int it = 0; it < 2000; ++it) {
    const auto a = static_cast<std::int64_t>(rng()) >> 2, b = static_cast<std::int64_t>(rng()) >> 3;
    const auto c = static_cast<std::int64_t>(rng()) >> 1;
    const Int128 exact = static_cast<Int128>(a) * b - c + a;
    const BigInt r = BigInt(a) * BigInt(b) - BigInt(c) + BigInt(a);
    EXPECT_EQ(r.sign(), (exact > 0) - (exact < 0));
    // Round trip of the low 64 bits through fromDouble of exact small values.
    EXPECT_EQ(BigInt::fromDouble(static_cast<double>(a >> 11), 0), BigInt(a >> 11));
  }
  EXPECT_EQ(BigInt::fromDouble(0.75, -2), BigInt(3));
  EXPECT_EQ(BigInt::fromDouble(-6.0, 1), BigInt(-3));
  EXPECT_EQ(lowExponent(0.75), -2);
  EXPECT_EQ(lowExponent(std::ldexp(1.0, -1074)), -1074);
}

TEST(Predicates, Conventions) {
  const double o[2] = {0, 0}, x[2] = {1, 0}, y[2] = {0, 1}, in[2] = {0.4, 0.4}, out[2] = {2, 2};
  EXPECT_GT(orient2d(o, x, y), 0);
  EXPECT_LT(orient2d(o, y, x), 0);
  EXPECT_GT(incircle(o, x, y, in), 0);
  EXPECT_LT(incircle(o, x, y, out), 0);
  EXPECT_LT(incircle(o, y, x, in), 0);  // clockwise: the sign flips
  const double O[3] = {0, 0, 0}, X[3] = {1, 0, 0}, Y[3] = {0, 1, 0}, Z[3] = {0, 0, 1};
  const double IN[3] = {0.25, 0.25, 0.25}, OUT[3] = {2, 2, 2};
  EXPECT_GT(orient3d(O, X, Y, Z), 0);
  EXPECT_LT(orient3d(O, Y, X, Z), 0);
  EXPECT_GT(insphere(O, X, Y, Z, IN), 0);
  EXPECT_LT(insphere(O, X, Y, Z, OUT), 0);
  EXPECT_LT(insphere(O, Y, X, Z, IN), 0);  // negative orientation: the sign flips
  // Magnitudes of well-conditioned inputs are the determinants themselves.
  EXPECT_DOUBLE_EQ(orient2d(o, x, y), 1.0);
  EXPECT_DOUBLE_EQ(orient3d(O, X, Y, Z), 1.0);
  // The reference agrees with the conventions.
  EXPECT_EQ(refOrient3d(O, X, Y, Z), 1);
  EXPECT_EQ(refInsphere(O, X, Y, Z, IN), 1);
  EXPECT_EQ(refIncircle(o, x, y, in), 1);
}

TEST(Predicates, RandomUniformMatchReference) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int it = 0; it < 1000; ++it) expectAllMatch(makePoints([&] { return u(rng); }));
}

TEST(Predicates, SmallIntegerGridsHitZeroExactly) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int> g(-3, 3);
  int zeros2 = 0, zerosC = 0, zeros3 = 0, zerosS = 0;
  for (int it = 0; it < 2000; ++it) {
    const Pts q = makePoints([&] { return static_cast<double>(g(rng)); });
    expectAllMatch(q);
    const double *a = q[0].data(), *b = q[1].data(), *c = q[2].data(), *d = q[3].data();
    zeros2 += orient2d(a, b, c) == 0.0;
    zerosC += incircle(a, b, c, d) == 0.0;
    zeros3 += orient3d(a, b, c, d) == 0.0;
    zerosS += insphere(a, b, c, d, q[4].data()) == 0.0;
  }
  // The coarse grid produces many degenerate configurations; each must give exactly 0.
  EXPECT_GT(zeros2, 50);
  EXPECT_GT(zerosC, 50);
  EXPECT_GT(zeros3, 20);
  EXPECT_GT(zerosS, 20);
}

TEST(Predicates, NearlyCollinearPerturbedByUlps) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-10.0, 10.0), t(-2.0, 3.0);
  int nonzeroBoth = 0;
  for (int it = 0; it < 300; ++it) {
    const double a[2] = {u(rng), u(rng)}, b[2] = {u(rng), u(rng)};
    const double tt = t(rng);
    const double c0[2] = {a[0] + tt * (b[0] - a[0]), a[1] + tt * (b[1] - a[1])};
    for (int dx = -2; dx <= 2; ++dx)
      for (int dy = -2; dy <= 2; ++dy) {
        double c[2] = {c0[0], c0[1]};
        for (int k = 0; k < std::abs(dx); ++k) c[0] = std::nextafter(c[0], dx > 0 ? 1e300 : -1e300);
        for (int k = 0; k < std::abs(dy); ++k) c[1] = std::nextafter(c[1], dy > 0 ? 1e300 : -1e300);
        const int s = sgn(orient2d(a, b, c));
        ASSERT_EQ(s, refOrient2d(a, b, c));
        ASSERT_EQ(sgn(orient2d(b, c, a)), s);   // cyclic
        ASSERT_EQ(sgn(orient2d(b, a, c)), -s);  // transposition
        nonzeroBoth += s != 0;
      }
  }
  EXPECT_GT(nonzeroBoth, 0);
}

TEST(Predicates, KettnerGridNearDiagonal) {
  // p on a 64×64 grid of ulp-steps around (0.5, 0.5), against the line through (12,12) and
  // (24,24): the naive double evaluation gets many of these wrong.
  const double q[2] = {12, 12}, r[2] = {24, 24};
  const double step = std::ldexp(1.0, -53);
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const double p[2] = {0.5 + i * step, 0.5 + j * step};
      ASSERT_EQ(sgn(orient2d(p, q, r)), refOrient2d(p, q, r)) << i << " " << j;
      ASSERT_EQ(sgn(orient2d(p, q, r)), (j > i) - (j < i));  // above the diagonal: ccw
    }
}

TEST(Predicates, NearlyCocircularAndCosphericalPerturbations) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> ang(0.0, 6.283185307179586);
  for (int it = 0; it < 300; ++it) {
    Pts q;
    for (auto& p : q) {
      const double th = ang(rng), ph = ang(rng) / 2;
      p = {std::cos(th) * std::sin(ph), std::sin(th) * std::sin(ph), std::cos(ph)};
    }
    // 2D: put the 4th point on the unit circle too (rounded), then perturb.
    double a[2] = {std::cos(1.0), std::sin(1.0)}, b[2] = {std::cos(2.5), std::sin(2.5)},
           c[2] = {std::cos(4.0), std::sin(4.0)};
    const double th = ang(rng);
    double d[2] = {std::cos(th), std::sin(th)};
    d[it % 2] = std::nextafter(d[it % 2], (it / 2) % 2 ? 2.0 : -2.0);
    ASSERT_EQ(sgn(incircle(a, b, c, d)), refIncircle(a, b, c, d));
    q[4][it % 3] = std::nextafter(q[4][it % 3], (it / 3) % 2 ? 2.0 : -2.0);
    expectAllMatch(q);
  }
}

TEST(Predicates, ExactlyCocircularIntegerPointsGiveZero) {
  // All integer points on x² + y² = 25 and 65² (65² = 16² + 63² = 25² + 60² = 33² + 56² …).
  std::vector<std::array<double, 2>> pts;
  for (int r2 : {25, 65 * 65}) {
    pts.clear();
    const int r = static_cast<int>(std::lround(std::sqrt(r2)));
    for (int x = -r; x <= r; ++x)
      for (int y = -r; y <= r; ++y)
        if (x * x + y * y == r2) pts.push_back({double(x), double(y)});
    ASSERT_GE(pts.size(), 12u);
    for (std::size_t i = 0; i + 3 < pts.size(); ++i) {
      const double *a = pts[i].data(), *b = pts[i + 1].data(), *c = pts[i + 2].data(),
                   *d = pts[i + 3].data();
      EXPECT_EQ(incircle(a, b, c, d), 0.0);
      // Same configuration translated by 2^40 and scaled by 2^±300: still exactly 0.
      for (double s : {std::ldexp(1.0, 300), std::ldexp(1.0, -300)}) {
        double A[2] = {a[0] * s, a[1] * s}, B[2] = {b[0] * s, b[1] * s}, C[2] = {c[0] * s, c[1] * s},
               D[2] = {d[0] * s, d[1] * s};
        EXPECT_EQ(incircle(A, B, C, D), 0.0);
      }
      const double off = std::ldexp(1.0, 40);
      double A[2] = {a[0] + off, a[1] - off}, B[2] = {b[0] + off, b[1] - off},
             C[2] = {c[0] + off, c[1] - off}, D[2] = {d[0] + off, d[1] - off};
      EXPECT_EQ(incircle(A, B, C, D), 0.0);
      // A point just inside / outside along the radius.
      double in[2] = {d[0] * 0.999999, d[1] * 0.999999};
      EXPECT_EQ(sgn(incircle(a, b, c, in)), refIncircle(a, b, c, in));
    }
  }
}

TEST(Predicates, ExactlyCosphericalIntegerPointsGiveZero) {
  std::vector<std::array<double, 3>> pts;  // x² + y² + z² = 81
  for (int x = -9; x <= 9; ++x)
    for (int y = -9; y <= 9; ++y)
      for (int z = -9; z <= 9; ++z)
        if (x * x + y * y + z * z == 81) pts.push_back({double(x), double(y), double(z)});
  ASSERT_GT(pts.size(), 30u);
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<std::size_t> pick(0, pts.size() - 1);
  const double off = 1e15;  // integers + 1e15 are still exact doubles
  for (int it = 0; it < 500; ++it) {
    const double *a = pts[pick(rng)].data(), *b = pts[pick(rng)].data(), *c = pts[pick(rng)].data(),
                 *d = pts[pick(rng)].data(), *e = pts[pick(rng)].data();
    EXPECT_EQ(insphere(a, b, c, d, e), 0.0);
    double A[3], B[3], C[3], D[3], E[3];
    for (int k = 0; k < 3; ++k) {
      A[k] = a[k] + off, B[k] = b[k] - off, C[k] = c[k] + off, D[k] = d[k] + off, E[k] = e[k] + off;
      B[k] += 2 * off;
    }
    EXPECT_EQ(insphere(A, B, C, D, E), 0.0);
    EXPECT_EQ(sgn(orient3d(A, B, C, D)), sgn(orient3d(a, b, c, d)));
    for (double s : {std::ldexp(1.0, 330), std::ldexp(1.0, -330)}) {
      for (int k = 0; k < 3; ++k) A[k] = a[k] * s, B[k] = b[k] * s, C[k] = c[k] * s, D[k] = d[k] * s, E[k] = e[k] * s;
      EXPECT_EQ(insphere(A, B, C, D, E), 0.0);
      EXPECT_EQ(sgn(orient3d(A, B, C, D)), sgn(orient3d(a, b, c, d)));
    }
  }
}

TEST(Predicates, ExtremeScalesMatchReference) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> g(-4, 4);
  for (double scale : {1e-100, 1e100, 1e-140, 1e140}) {
    for (int it = 0; it < 150; ++it) {
      // Random points, and coarse-grid points (degenerate) scaled by a non-power of two.
      expectAllMatch(makePoints([&] { return u(rng) * scale; }));
      const Pts q = makePoints([&] { return g(rng) * scale; });
      expectAllMatch(q);
    }
  }
  // Power-of-two scaling multiplies each determinant by a positive factor: signs unchanged.
  for (int it = 0; it < 200; ++it) {
    const Pts q = makePoints([&] { return static_cast<double>(g(rng)) + 0.5 * u(rng); });
    for (int e : {-330, 330}) {
      Pts s = q;
      for (auto& p : s)
        for (double& x : p) x = std::ldexp(x, e);
      EXPECT_EQ(sgn(insphere(s[0].data(), s[1].data(), s[2].data(), s[3].data(), s[4].data())),
                sgn(insphere(q[0].data(), q[1].data(), q[2].data(), q[3].data(), q[4].data())));
      EXPECT_EQ(sgn(incircle(s[0].data(), s[1].data(), s[2].data(), s[3].data())),
                sgn(incircle(q[0].data(), q[1].data(), q[2].data(), q[3].data())));
    }
  }
}

TEST(Predicates, MixedMagnitudesMatchReference) {
  // Coordinates spanning 1e-200 .. 1e200 in the same call (the big-integer fallback).
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> ex(-200, 200);
  for (int it = 0; it < 150; ++it) {
    expectAllMatch(makePoints([&] { return u(rng) * std::pow(10.0, ex(rng)); }));
    // Nearly degenerate: tiny perturbations of a grid configuration.
    std::uniform_int_distribution<int> g(-2, 2);
    Pts q = makePoints([&] { return static_cast<double>(g(rng)); });
    q[it % 5][it % 3] += 1e-200 * u(rng);
    expectAllMatch(q);
  }
}

TEST(Predicates, LargeTranslationsMatchReference) {
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> g(-3, 3);
  for (double off : {1e6, 1e12, 3e15, -1e30}) {
    for (int it = 0; it < 200; ++it) {
      expectAllMatch(makePoints([&] { return off + u(rng); }));
      expectAllMatch(makePoints([&] { return off + g(rng) * 0.25; }));
    }
  }
}

TEST(Predicates, ExpansionAndIntegerPathsMatchReference) {
  // The exact stages called directly (the public functions reach them only when the
  // filter cannot decide): random, coarse-grid (degenerate) and translated inputs.
  namespace d = aniso::predicates::detail;
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> g(-2, 2);
  for (int it = 0; it < 600; ++it) {
    const int mode = it % 3;
    const Pts q = makePoints([&] {
      return mode == 0 ? u(rng) : mode == 1 ? static_cast<double>(g(rng)) : 1e9 + 0.125 * g(rng) + u(rng) * 1e-7;
    });
    const double *a = q[0].data(), *b = q[1].data(), *c = q[2].data(), *dd = q[3].data(),
                 *e = q[4].data();
    const double p2[8] = {a[0], a[1], b[0], b[1], c[0], c[1], dd[0], dd[1]};
    double p3[15];
    for (int i = 0; i < 5; ++i)
      for (int k = 0; k < 3; ++k) p3[3 * i + k] = q[i][k];
    const int r2 = refOrient2d(p2, p2 + 2, p2 + 4), rc = refIncircle(p2, p2 + 2, p2 + 4, p2 + 6);
    const int r3 = refOrient3d(a, b, c, dd), rs = refInsphere(a, b, c, dd, e);
    ASSERT_EQ(sgn(d::orient2dExpansion(p2)), r2);
    ASSERT_EQ(sgn(d::orient2dBig(p2)), r2);
    ASSERT_EQ(sgn(d::incircleExpansion(p2)), rc);
    ASSERT_EQ(sgn(d::incircleBig(p2)), rc);
    ASSERT_EQ(sgn(d::orient3dExpansion(p3)), r3);
    ASSERT_EQ(sgn(d::orient3dBig(p3)), r3);
    ASSERT_EQ(sgn(d::insphereExpansion(p3)), rs);
    ASSERT_EQ(sgn(d::insphereBig(p3)), rs);
  }
}

TEST(Predicates, AntisymmetryUnderPermutations) {
  std::mt19937_64 rng(23);
  std::uniform_int_distribution<int> g(-2, 2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int it = 0; it < 500; ++it) {
    const Pts q = makePoints([&] { return it % 2 ? static_cast<double>(g(rng)) : u(rng); });
    const double *a = q[0].data(), *b = q[1].data(), *c = q[2].data(), *d = q[3].data(),
                 *e = q[4].data();
    const int s2 = sgn(incircle(a, b, c, d));
    EXPECT_EQ(sgn(incircle(b, a, c, d)), -s2);
    EXPECT_EQ(sgn(incircle(a, c, b, d)), -s2);
    EXPECT_EQ(sgn(incircle(b, c, a, d)), s2);
    EXPECT_EQ(sgn(incircle(a, b, d, c)), -s2);  // swapping the query point with a vertex
    const int s3 = sgn(orient3d(a, b, c, d));
    EXPECT_EQ(sgn(orient3d(b, a, c, d)), -s3);
    EXPECT_EQ(sgn(orient3d(a, b, d, c)), -s3);
    EXPECT_EQ(sgn(orient3d(b, c, a, d)), s3);
    const int s4 = sgn(insphere(a, b, c, d, e));
    EXPECT_EQ(sgn(insphere(b, a, c, d, e)), -s4);
    EXPECT_EQ(sgn(insphere(a, b, c, e, d)), -s4);
    EXPECT_EQ(sgn(insphere(c, d, a, b, e)), s4);
  }
}
