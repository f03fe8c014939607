// MetricArcLength: adaptive sampling of the metric density along a curve and the inverse
// of its arc length (see MetricArcLength.h).
#include "mesher/surface/contour/MetricArcLength.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mesher/core/Error.h"

namespace aniso::contour {

MetricArcLength::MetricArcLength(const std::function<double(double)>& density, double t0,
                                 double t1, const ArcLengthOptions& options)
    : opt_(options), t0_(t0), t1_(t1) {
  if (!(t0 < t1) || !std::isfinite(t0) || !std::isfinite(t1)) {
    std::ostringstream s;
    s << "empty or non-finite parameter range [" << t0 << ", " << t1 << "]";
    throw MeshingError(s.str());
  }
  const int pieces = std::max(1, opt_.initialPieces);
  t_.push_back(t0);
  rho_.push_back(eval(density, t0));
  for (int i = 1; i <= pieces; ++i) {
    const double a = t_.back(), ra = rho_.back();
    const double b = i == pieces ? t1 : t0 + (t1 - t0) * i / pieces;
    refine(density, a, ra, b, eval(density, b), 0);
  }
  s_.assign(t_.size(), 0.0);
  for (std::size_t i = 1; i < t_.size(); ++i)
    s_[i] = s_[i - 1] + 0.5 * (t_[i] - t_[i - 1]) * (rho_[i] + rho_[i - 1]);
}

double MetricArcLength::eval(const std::function<double(double)>& density, double t) const {
  const double r = density(t);
  if (!(r >= 0) || !std::isfinite(r)) {
    std::ostringstream s;
    s << "metric density " << r << " at t = " << t << " (not finite or negative)";
    throw MeshingError(s.str());
  }
  return r;
}

void MetricArcLength::refine(const std::function<double(double)>& density, double a, double ra,
                             double b, double rb, int depth) {
  const double h = b - a;
  const double m = a + 0.5 * h;
  const double rm = eval(density, m);
  const double whole = 0.5 * h * (ra + rb);
  const double halves = 0.25 * h * (ra + 2 * rm + rb);
  const double tol = std::max(opt_.relTol * halves, opt_.absTol * h / (t1_ - t0_));
  const bool converged = std::abs(whole - halves) <= tol && halves <= opt_.maxPieceLength;
  // Round-off level pieces cannot be refined further.
  const bool tiny = !(a < m && m < b);
  if (converged || tiny || depth >= opt_.maxDepth) {
    if (!tiny) {
      t_.push_back(m);
      rho_.push_back(rm);
    }
    t_.push_back(b);
    rho_.push_back(rb);
    return;
  }
  refine(density, a, ra, m, rm, depth + 1);
  refine(density, m, rm, b, rb, depth + 1);
}

double MetricArcLength::parameterAt(double s) const {
  const double total = s_.back();
  if (!(total > 0)) return t0_;
  s = std::clamp(s, 0.0, total);
  if (s >= total) return t1_;
  // The piece [t_j, t_j+1] with s_j <= s < s_j+1.
  const std::size_t j = static_cast<std::size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin()) - 1;
  const double h = t_[j + 1] - t_[j];
  const double d = s - s_[j];  // >= 0
  // s_j + ρ_j τ + (ρ_j+1 − ρ_j) τ² / (2h) = s, solved in the cancellation-free form.
  const double a = (rho_[j + 1] - rho_[j]) / (2 * h), b = rho_[j];
  const double disc = std::max(0.0, b * b + 4 * a * d);
  const double denom = b + std::sqrt(disc);
  const double tau = denom > 0 ? 2 * d / denom : 0.0;
  return t_[j] + std::clamp(tau, 0.0, h);
}

std::vector<double> MetricArcLength::equalSpacing(int n) const {
  n = std::max(1, n);
  std::vector<double> out(static_cast<std::size_t>(n) + 1);
  out.front() = t0_;
  out.back() = t1_;
  for (int i = 1; i < n; ++i)
    out[i] = total() > 0 ? parameterAt(total() * i / n) : t0_ + (t1_ - t0_) * i / n;
  return out;
}

}  // namespace aniso::contour
