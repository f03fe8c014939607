#pragma once
// parallelFor — the one way the meshers run independent items (faces, solids) in parallel.
// Items are handed out in index order from an atomic counter; each item writes only its own
// result slot, so the output does not depend on the number of threads. The first exception
// thrown by an item is rethrown once every thread has stopped (the remaining items are
// skipped); when it is Cancelled (Cancel.h), the shared token is raised, so the items
// still running stop at their next check. Progress is reported per finished item through PhaseProgress, whose optional
// detail (e.g. the predicted element count) is refreshed with every report.
#include <algorithm>
#include <atomic>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "mesher/core/Log.h"

namespace aniso {

/// The progress of a parallel phase. tick() may be called from any thread.
struct PhaseProgress {
  PhaseProgress(const char* phase, int n, std::function<std::string()> detailFn = {})
      : progress(phase, n), detail(std::move(detailFn)) {}
  void tick(bool force = false) { progress.update(done.load(), detail ? detail() : std::string(), force); }
  Progress progress;
  std::atomic<int> done{0};
  std::function<std::string()> detail;
};

/// Runs work(i) for i in [0, n) on `threads` threads (0 = all cores).
template <class Work>
void parallelFor(int n, int threads, Work work, PhaseProgress& progress) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::clamp(threads, 1, std::max(1, n));
  std::atomic<int> next{0};
  std::exception_ptr error;
  std::mutex errorMutex;
  auto run = [&] {
    for (int i = next++; i < n; i = next++) {
      try {
        work(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(errorMutex);
        if (!error) error = std::current_exception();
        next = n;
      }
      ++progress.done;
      progress.tick();
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(run);
  run();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  progress.tick(true);  // the final state, whatever the rate limit let through
}

template <class Work>
void parallelFor(int n, int threads, Work work, const char* phase) {
  PhaseProgress progress(phase, n);
  parallelFor(n, threads, work, progress);
}

}  // namespace aniso
