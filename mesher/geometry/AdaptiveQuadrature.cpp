// Adaptive Gauss–Kronrod 7/15 quadrature (nodes and weights of QUADPACK's qk15).
#include "mesher/geometry/AdaptiveQuadrature.h"

#include <cmath>

namespace aniso {

namespace {

constexpr double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                            0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                            0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                            0.207784955007898467600689403773245, 0.0};
constexpr double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                            0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                            0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                            0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
// Gauss 7-point weights for the Kronrod nodes 1, 3, 5, 7.
constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                           0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Estimate {
  double kronrod, error;
};

Estimate gaussKronrod(const std::function<double(double)>& f, double a, double b) {
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  const double fc = f(c);
  double k = kWgk[7] * fc, g = kWg[3] * fc;
  for (int i = 0; i < 7; ++i) {
    const double s = f(c - h * kXgk[i]) + f(c + h * kXgk[i]);
    k += kWgk[i] * s;
    if (i % 2 == 1) g += kWg[i / 2] * s;
  }
  return {k * h, std::abs((k - g) * h)};
}

double refine(const std::function<double(double)>& f, double a, double b, const Estimate& e,
              double tol, int depth) {
  if (e.error <= tol || depth <= 0 || !std::isfinite(e.kronrod)) return e.kronrod;
  const double m = 0.5 * (a + b);
  if (m <= a || m >= b) return e.kronrod;  // interval at round-off level
  const Estimate left = gaussKronrod(f, a, m), right = gaussKronrod(f, m, b);
  return refine(f, a, m, left, 0.5 * tol, depth - 1) + refine(f, m, b, right, 0.5 * tol, depth - 1);
}

}  // namespace

double integrateAdaptive(const std::function<double(double)>& f, double a, double b, double relTol,
                         int maxDepth) {
  if (a == b) return 0;
  if (b < a) return -integrateAdaptive(f, b, a, relTol, maxDepth);
  const Estimate whole = gaussKronrod(f, a, b);
  const double tol = relTol * std::abs(whole.kronrod) + 1e-300;
  return refine(f, a, b, whole, tol, maxDepth);
}

}  // namespace aniso
