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

/// Runs work(thread, i) for i in [begin, end) on up to `threads` threads (0 = all cores;
/// thread 0 is the caller's, so that per-thread scratch can be indexed by it), one i at a
/// time from a shared counter; the first exception is rethrown once every thread has
/// stopped (the items not yet started are skipped).
template <class Work>
void parallelForOnThreads(std::size_t begin, std::size_t end, int threads, Work work) {
  if (end <= begin) return;
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(threads), end - begin));
  if (threads <= 1) {
    for (std::size_t i = begin; i < end; ++i) work(0, i);
    return;
  }
  std::atomic<std::size_t> next{begin};
  std::exception_ptr error;
  std::mutex errorMutex;
  auto run = [&](int thread) {
    try {
      for (std::size_t i = next++; i < end; i = next++) work(thread, i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(errorMutex);
      if (!error) error = std::current_exception();
      next = end;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(run, t);
  run(0);
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

/// Runs work(i) for i in [0, n) on `threads` threads (0 = all cores), progress ticked per
/// finished item (also one that threw).
template <class Work>
void parallelFor(int n, int threads, Work work, PhaseProgress& progress) {
  parallelForOnThreads(0, static_cast<std::size_t>(std::max(0, n)), threads, [&](int, std::size_t i) {
    struct Tick {
      PhaseProgress& p;
      ~Tick() {
        ++p.done;
        p.tick();
      }
    } tick{progress};
    work(static_cast<int>(i));
  });
  progress.tick(true);  // the final state, whatever the rate limit let through
}

template <class Work>
void parallelFor(int n, int threads, Work work, const char* phase) {
  PhaseProgress progress(phase, n);
  parallelFor(n, threads, work, progress);
}

}  // namespace aniso
