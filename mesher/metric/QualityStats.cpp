#include "mesher/metric/QualityStats.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesher/core/Error.h"

namespace aniso {

void QualityStats::add(double value) {
  if (!std::isfinite(value)) throw MeshingError("quality statistics: non-finite value " + std::to_string(value));
  ++n_;
  const double delta = value - mean_;
  mean_ += delta / static_cast<double>(n_);
  m2_ += delta * (value - mean_);
  min_ = std::min(min_, value);
  max_ = std::max(max_, value);
}

void QualityStats::addAll(std::span<const double> values) {
  if (values.empty()) return;
  QualityStats b;
  double sum = 0;
  for (const double v : values) {
    if (!std::isfinite(v)) throw MeshingError("quality statistics: non-finite value " + std::to_string(v));
    sum += v;
    b.min_ = std::min(b.min_, v);
    b.max_ = std::max(b.max_, v);
  }
  b.n_ = values.size();
  b.mean_ = sum / static_cast<double>(b.n_);
  for (const double v : values) b.m2_ += (v - b.mean_) * (v - b.mean_);
  merge(b);
}

void QualityStats::merge(const QualityStats& o) {
  if (o.n_ == 0) return;
  if (n_ == 0) {
    *this = o;
    return;
  }
  const double na = static_cast<double>(n_), nb = static_cast<double>(o.n_), n = na + nb;
  const double delta = o.mean_ - mean_;
  mean_ += delta * nb / n;
  m2_ += o.m2_ + delta * delta * na * nb / n;
  n_ += o.n_;
  min_ = std::min(min_, o.min_);
  max_ = std::max(max_, o.max_);
}

double QualityStats::stddev() const { return std::sqrt(std::max(variance(), 0.0)); }

}  // namespace aniso
