#include "mesher/core/Log.h"

#include <chrono>
#include <mutex>

namespace aniso {
namespace {
std::mutex& sinkMutex() {
  static std::mutex m;
  return m;
}
std::shared_ptr<LogSink>& sinkRef() {
  static std::shared_ptr<LogSink> s;
  return s;
}
std::shared_ptr<LogSink> currentSink() {
  std::lock_guard<std::mutex> lock(sinkMutex());
  return sinkRef();
}
long long nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}
}  // namespace

std::shared_ptr<LogSink> setLogSink(std::shared_ptr<LogSink> sink) {
  std::lock_guard<std::mutex> lock(sinkMutex());
  std::swap(sinkRef(), sink);
  return sink;
}

void log(LogLevel level, const std::string& text) {
  if (auto s = currentSink()) s->message(level, text);
}

Progress::Progress(std::string phase, double total) : phase_(std::move(phase)), total_(total) {
  if (auto s = currentSink()) s->progressBegin(phase_, total_);
  lastNs_ = nowNs();
}

Progress::~Progress() {
  if (auto s = currentSink()) s->progressEnd(phase_);
}

void Progress::update(double done, const std::string& detail, bool force) {
  const long long t = nowNs();
  long long last = lastNs_.load(std::memory_order_relaxed);
  // At most 10 updates per second; of concurrent callers only the one that moves the
  // time stamp reports.
  if (!force &&
      (t - last < 100'000'000 || !lastNs_.compare_exchange_strong(last, t, std::memory_order_relaxed)))
    return;
  if (auto s = currentSink()) s->progress(phase_, done, total_, detail);
}

}  // namespace aniso
