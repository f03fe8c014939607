#pragma once
// QualityStats — running count, mean, standard deviation, minimum and maximum of a
// quality measure (the quality block of the report: η̄_M eq. 2.48, μ̄_M eq. 2.49,
// Ē_K eq. 2.51).
//
// Welford's update (numerically stable in one pass); merge() combines accumulators of
// separate threads (Chan et al.). stddev() is the population standard deviation
// (divide by n), 0 for fewer than two values. Non-finite values are rejected with
// MeshingError (a NaN quality is a bug upstream, not a statistic). Empty accumulator:
// count 0, mean and stddev 0, min() = +infinity, max() = −infinity.
#include <cstddef>
#include <limits>
#include <span>

namespace aniso {

class QualityStats {
 public:
  void add(double value);
  /// add() of every value, to rounding: the block's mean and squared deviations in two
  /// passes (as stable as Welford's), merged as merge() does — for blocks of values
  /// gathered in a hot loop (one division per block, not per value).
  void addAll(std::span<const double> values);
  void merge(const QualityStats& other);

  std::size_t count() const { return n_; }
  double mean() const { return mean_; }
  double variance() const { return n_ > 1 ? m2_ / static_cast<double>(n_) : 0.0; }
  double stddev() const;
  double min() const { return min_; }
  double max() const { return max_; }

 private:
  std::size_t n_ = 0;
  double mean_ = 0, m2_ = 0;
  double min_ = std::numeric_limits<double>::infinity();
  double max_ = -std::numeric_limits<double>::infinity();
};

}  // namespace aniso
