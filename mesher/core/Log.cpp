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
  if (auto s = currentSink()) s->progress(phase_, 0, total_, {});
  lastNs_ = nowNs();
}

Progress::~Progress() {
  if (auto s = currentSink()) s->progressEnd(phase_);
}

void Progress::update(double done, const std::string& detail) {
  const long long t = nowNs();
  if (t - lastNs_ < 100'000'000) return;  // at most 10 updates per second
  lastNs_ = t;
  if (auto s = currentSink()) s->progress(phase_, done, total_, detail);
}

}  // namespace aniso
