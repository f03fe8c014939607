// Nearest-parameter search: uniform bracketing, then safeguarded Newton on g'.
#include "mesher/geometry/CurveProjection.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace aniso {

namespace {

constexpr double kStationary = 1e-12;

/// eval(t), with a throwing evaluation reported as a non-finite sample.
DistanceSample safeEval(const std::function<DistanceSample(double)>& eval, double t) {
  try {
    return eval(t);
  } catch (...) {
    return DistanceSample{HUGE_VAL, 0, 0};
  }
}

struct Best {
  double t = 0, g = HUGE_VAL;
};

/// Safeguarded Newton on g' inside [a, b], starting at t. Returns the converged iterate
/// (g' = 0 to round-off, more precise than comparing values of g, which is flat there), or
/// the point of lowest g seen when the iteration stops without converging.
Best refineBracket(const std::function<DistanceSample(double)>& eval, double a, double b,
                   double t, const DistanceSample& first) {
  Best best{t, first.g};
  const double eps = 1e-15 * std::max({1.0, std::abs(a), std::abs(b)});
  DistanceSample s = first;
  for (int it = 0; it < 100; ++it) {
    if (std::abs(s.dg) <= kStationary * s.dgScale) return {t, s.g};
    if (s.dg > 0) b = t;
    else if (s.dg < 0) a = t;
    else return {t, s.g};
    if (b - a <= eps) return {t, s.g};
    double tn = (s.ddg > 0 && std::isfinite(s.ddg)) ? t - s.dg / s.ddg : 0.5 * (a + b);
    if (!(tn > a && tn < b)) tn = 0.5 * (a + b);
    const double move = std::abs(tn - t);
    const DistanceSample sn = safeEval(eval, tn);
    if (!std::isfinite(sn.g)) break;
    t = tn;
    s = sn;
    if (s.g < best.g) best = {t, s.g};
    if (move <= eps) return {t, s.g};
  }
  return best;
}

}  // namespace

double nearestParameter(const std::function<DistanceSample(double)>& eval, double ts, double t0,
                        double t1, int samples) {
  const double lo = std::min(t0, t1), hi = std::max(t0, t1);
  if (!std::isfinite(lo) || !std::isfinite(hi)) return std::isfinite(ts) ? ts : 0.0;
  if (!std::isfinite(ts)) ts = 0.5 * (lo + hi);
  ts = std::clamp(ts, lo, hi);
  if (lo == hi) return lo;

  const int n = std::max(2, samples);
  std::vector<double> t;
  t.reserve(n + 2);
  for (int i = 0; i <= n; ++i) t.push_back(i == n ? hi : lo + (hi - lo) * i / n);
  t.insert(std::upper_bound(t.begin(), t.end(), ts), ts);
  t.erase(std::unique(t.begin(), t.end()), t.end());
  std::vector<DistanceSample> s(t.size());
  for (size_t i = 0; i < t.size(); ++i) s[i] = safeEval(eval, t[i]);

  std::vector<Best> candidates;
  double gMax = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(s[i].g)) continue;
    gMax = std::max(gMax, s[i].g);
    const bool leftOk = i == 0 || !(s[i - 1].g < s[i].g);
    const bool rightOk = i + 1 == t.size() || !(s[i + 1].g < s[i].g);
    if (!leftOk || !rightOk) continue;
    const double a = i == 0 ? t[i] : t[i - 1];
    const double b = i + 1 == t.size() ? t[i] : t[i + 1];
    candidates.push_back(refineBracket(eval, a, b, t[i], s[i]));
  }
  if (candidates.empty()) return ts;
  const double gMin = std::min_element(candidates.begin(), candidates.end(),
                                       [](const Best& x, const Best& y) { return x.g < y.g; })->g;
  const double tie = 1e-12 * gMin + 1e-24 * gMax;
  Best chosen{ts, HUGE_VAL};
  double chosenGap = HUGE_VAL;
  for (const Best& c : candidates) {
    if (c.g > gMin + tie) continue;
    const double gap = std::abs(c.t - ts);
    if (gap < chosenGap) { chosen = c; chosenGap = gap; }
  }
  return chosen.t;
}

}  // namespace aniso
