#pragma once
// PredictionBoard — the predicted final element count of a phase that meshes several items
// (faces, solids) in parallel (thesis 6.5): each item posts its latest prediction (eq. 6.2
// at the start of its refinement, eq. 6.1 while refining, the actual count when done) and
// the progress display shows the sum. Items not started yet count 0, so the sum grows
// towards the final count. Lock-free; post() and total() may be called from any thread.
#include <atomic>
#include <cstddef>
#include <vector>

namespace aniso {

class PredictionBoard {
 public:
  explicit PredictionBoard(std::size_t items) : values_(items) {
    for (auto& v : values_) v.store(0.0, std::memory_order_relaxed);
  }
  void post(std::size_t item, double predicted) { values_.at(item).store(predicted, std::memory_order_relaxed); }
  double total() const {
    double s = 0;
    for (const auto& v : values_) s += v.load(std::memory_order_relaxed);
    return s;
  }

 private:
  std::vector<std::atomic<double>> values_;
};

}  // namespace aniso
