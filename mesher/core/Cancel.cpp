#include "mesher/core/Cancel.h"

#include <cmath>
#include <cstdio>

namespace aniso {

CancelToken::CancelToken(double seconds)
    : limitSeconds_(seconds),
      deadline_(Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds))) {}

bool CancelToken::stopped() const {
  if (requested_.load(std::memory_order_relaxed)) return true;
  if (limitSeconds_ > 0 && Clock::now() >= deadline_) {
    request();
    return true;
  }
  return false;
}

void CancelToken::check(const char* phase) const {
  if (!stopped()) return;
  if (limitSeconds_ <= 0) throw Cancelled(std::string("stopped on request during ") + phase, phase);
  char limit[32];
  std::snprintf(limit, sizeof limit, "%g", limitSeconds_);
  throw Cancelled(std::string("stopped after the time limit of ") + limit + " s during " + phase, phase);
}

}  // namespace aniso
