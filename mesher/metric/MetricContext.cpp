#include "mesher/metric/MetricContext.h"

#include <atomic>

namespace aniso::detail {

std::uint64_t reserveMetricCounterBlock() {
  // Starts at 1: counter value 0 means "never computed" in MetricCoords.
  static std::atomic<std::uint64_t> next{1};
  return next.fetch_add(kMetricCounterBlock, std::memory_order_relaxed);
}

}  // namespace aniso::detail
