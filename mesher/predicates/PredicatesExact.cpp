// Exact evaluations of the four predicates: one formula per predicate, written once as a
// template over the number type and instantiated for floating-point expansions (fast,
// range-limited) and for big integers (slow, unlimited). See PredicatesExact.h.
#include "mesher/predicates/PredicatesExact.h"

#include <algorithm>
#include <cmath>

#include "mesher/predicates/ExactInteger.h"
#include "mesher/predicates/Expansion.h"

namespace aniso::predicates::detail {
namespace {

// ---- number type over expansions: every result lives in the evaluation's arena ----
struct ExNum {
  Arena* ar;
  Ex x;
};
ExNum operator+(ExNum a, ExNum b) { return {a.ar, sum(*a.ar, a.x, b.x)}; }
ExNum operator-(ExNum a, ExNum b) { return {a.ar, diff(*a.ar, a.x, b.x)}; }
ExNum operator*(ExNum a, ExNum b) { return {a.ar, product(*a.ar, a.x, b.x)}; }

// ---- the formulas (conventions of Predicates.h), on packed coordinates ----

/// det[b−a, c−a].
template <class N>
N orient2dFormula(const N* p) {
  const N* a = p;
  const N* b = p + 2;
  const N* c = p + 4;
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/// det of the rows (x_i, y_i, x_i² + y_i²) of a − d, b − d, c − d.
template <class N>
N incircleFormula(const N* p) {
  N x[3], y[3], w[3];
  for (int i = 0; i < 3; ++i) {
    x[i] = p[2 * i] - p[6];
    y[i] = p[2 * i + 1] - p[7];
    w[i] = x[i] * x[i] + y[i] * y[i];
  }
  const N mbc = x[1] * y[2] - x[2] * y[1];
  const N mca = x[2] * y[0] - x[0] * y[2];
  const N mab = x[0] * y[1] - x[1] * y[0];
  return (w[0] * mbc + w[1] * mca) + w[2] * mab;
}

/// det[b−a, c−a, d−a] = u · (v × w).
template <class N>
N orient3dFormula(const N* p) {
  N u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = p[3 + k] - p[k];
    v[k] = p[6 + k] - p[k];
    w[k] = p[9 + k] - p[k];
  }
  return u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/// −det of the rows (x_i, y_i, z_i, |·|²) of a − e, …, d − e (the sign makes it positive
/// for e inside when orient3d(a,b,c,d) > 0).
template <class N>
N insphereFormula(const N* p) {
  N x[4], y[4], z[4], w[4];
  for (int i = 0; i < 4; ++i) {
    x[i] = p[3 * i] - p[12];
    y[i] = p[3 * i + 1] - p[13];
    z[i] = p[3 * i + 2] - p[14];
    w[i] = (x[i] * x[i] + y[i] * y[i]) + z[i] * z[i];
  }
  auto m = [&](int i, int j) { return x[i] * y[j] - x[j] * y[i]; };
  const N mab = m(0, 1), mac = m(0, 2), mad = m(0, 3), mbc = m(1, 2), mbd = m(1, 3),
          mcd = m(2, 3);
  // 3×3 minors on (x, y, z), expanded along z.
  const N cabc = (z[0] * mbc - z[1] * mac) + z[2] * mab;
  const N cabd = (z[0] * mbd - z[1] * mad) + z[3] * mab;
  const N cacd = (z[0] * mcd - z[2] * mad) + z[3] * mac;
  const N cbcd = (z[1] * mcd - z[2] * mbd) + z[3] * mbc;
  // Laplace along the lifted column: det = −w_a C_bcd + w_b C_acd − w_c C_abd + w_d C_abc;
  // the result is −det.
  return (w[0] * cbcd - w[1] * cacd) + (w[2] * cabd - w[3] * cabc);
}

template <int NC, class F>
double viaExpansion(const double* p, F formula) {
  Arena ar;
  ExNum c[NC];
  for (int i = 0; i < NC; ++i) {
    double* v = ar.get(1);
    v[0] = p[i];
    c[i] = {&ar, Ex{v, p[i] != 0.0 ? 1 : 0}};
  }
  return formula(c).x.estimate();
}

template <int NC, class F>
double viaBig(const double* p, int degree, F formula) {
  int e0 = 0;
  bool any = false;
  for (int i = 0; i < NC; ++i) {
    if (p[i] == 0.0) continue;
    const int le = lowExponent(p[i]);
    e0 = any ? std::min(e0, le) : le;
    any = true;
  }
  BigInt c[NC];
  for (int i = 0; i < NC; ++i) c[i] = BigInt::fromDouble(p[i], e0);
  const BigInt r = formula(c);
  if (r.sign() == 0) return 0.0;
  int ex = 0;
  const double m = r.approx(ex);
  // value = m · 2^(ex + degree·e0); clamp the exponent so the result keeps its sign.
  const long total = static_cast<long>(ex) + static_cast<long>(degree) * e0;
  return std::ldexp(m, static_cast<int>(std::clamp(total, -1000L, 1000L)));
}

}  // namespace

double orient2dExpansion(const double* p) {
  return viaExpansion<6>(p, [](const ExNum* c) { return orient2dFormula(c); });
}
double incircleExpansion(const double* p) {
  return viaExpansion<8>(p, [](const ExNum* c) { return incircleFormula(c); });
}
double orient3dExpansion(const double* p) {
  return viaExpansion<12>(p, [](const ExNum* c) { return orient3dFormula(c); });
}
double insphereExpansion(const double* p) {
  return viaExpansion<15>(p, [](const ExNum* c) { return insphereFormula(c); });
}

double orient2dBig(const double* p) {
  return viaBig<6>(p, 2, [](const BigInt* c) { return orient2dFormula(c); });
}
double incircleBig(const double* p) {
  return viaBig<8>(p, 4, [](const BigInt* c) { return incircleFormula(c); });
}
double orient3dBig(const double* p) {
  return viaBig<12>(p, 3, [](const BigInt* c) { return orient3dFormula(c); });
}
double insphereBig(const double* p) {
  return viaBig<15>(p, 5, [](const BigInt* c) { return insphereFormula(c); });
}

}  // namespace aniso::predicates::detail
