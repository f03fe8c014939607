#pragma once
// CancelToken — how a run is stopped from outside the meshers: a deadline (--time-limit)
// and a flag any thread may raise. The meshers hold it through MeshOptions::cancel and
// call check(phase) in every long loop (per face, per solid, per refinement or improvement
// pass, every few hundred insertions); check() throws Cancelled naming the phase, which
// unwinds the whole run (no partial result). Once one thread has seen the deadline, the
// flag is raised, so the other workers of a parallelFor stop at their next check.
//
// Cost: check() is an atomic load plus, when a deadline is set, one steady_clock read;
// CancelPoll spaces the clock reads out in the innermost loops.
#include <atomic>
#include <chrono>
#include <memory>
#include <string>

#include "mesher/core/Error.h"

namespace aniso {

/// The run was stopped (time limit or request) during `phase`: exit 3, no output.
class Cancelled : public MeshingError {
 public:
  Cancelled(const std::string& message, std::string phase) : MeshingError(message), phase_(std::move(phase)) {}
  const std::string& phase() const { return phase_; }

 private:
  std::string phase_;
};

class CancelToken {
 public:
  using Clock = std::chrono::steady_clock;
  /// No deadline: stops only when request() is called.
  CancelToken() = default;
  /// Stops once `seconds` have passed since construction (seconds > 0).
  explicit CancelToken(double seconds);

  /// Asks every holder to stop at its next check (thread-safe).
  void request() const { requested_.store(true, std::memory_order_relaxed); }
  /// True once requested or past the deadline.
  bool stopped() const;
  /// Throws Cancelled ("stopped after the time limit of S s during PHASE") when stopped().
  void check(const char* phase) const;

 private:
  double limitSeconds_ = 0;  ///< 0: no deadline
  Clock::time_point deadline_{};
  mutable std::atomic<bool> requested_{false};
};

/// check() of an optional token (null: never stops).
inline void checkCancel(const CancelToken* token, const char* phase) {
  if (token) token->check(phase);
}

/// For the innermost loops: tick() checks the token every `period` calls only.
class CancelPoll {
 public:
  CancelPoll(const CancelToken* token, const char* phase, unsigned period = 64)
      : token_(token), phase_(phase), period_(period) {}
  void tick() {
    if (token_ && ++count_ >= period_) {
      count_ = 0;
      token_->check(phase_);
    }
  }

 private:
  const CancelToken* token_;
  const char* phase_;
  unsigned period_;
  unsigned count_ = 0;
};

}  // namespace aniso
