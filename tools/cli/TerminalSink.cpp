#include "tools/cli/TerminalSink.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace aniso::cli {
namespace {

/// The phase name a parser can split on: spaces become '_'.
std::string token(std::string name) {
  std::replace(name.begin(), name.end(), ' ', '_');
  return name;
}

double secondsBetween(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

TerminalSink::TerminalSink(int verbosity, bool progressLines)
    : verbosity_(verbosity), tty_(::isatty(2) != 0), lines_(progressLines) {}

void TerminalSink::message(LogLevel level, const std::string& text) {
  const LogLevel minLevel = verbosity_ < 0 ? LogLevel::Error : verbosity_ > 0 ? LogLevel::Debug : LogLevel::Notice;
  if (level < minLevel) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (lineOpen_) {
    std::fputs("\r\033[K", stderr);
    lineOpen_ = false;
  }
  const char* tag = level == LogLevel::Warning ? "warning: " : level == LogLevel::Error ? "error: " : "";
  std::fprintf(stderr, "anisomesh: %s%s\n", tag, text.c_str());
}

std::string TerminalSink::etaText(double done, double total) const {
  if (!(total > 0)) return {};
  const double f = done / total, elapsed = secondsBetween(rootStart_, Clock::now());
  if (f < kEtaMinFraction || f >= 1 || elapsed < kEtaMinSeconds) return {};
  char buf[32];
  std::snprintf(buf, sizeof buf, "eta %.0fs", elapsed * (1 - f) / f);
  return buf;
}

/// The terminal line (or, in --progress mode, a line) for the top-level phase; the caller
/// holds the mutex.
void TerminalSink::showLine(const std::string& phase, double done, double total, const std::string& detail,
                            bool force) {
  const auto now = Clock::now();
  std::string text = token(phase);
  const auto append = [&text](const std::string& word) {
    if (!word.empty()) text += " " + word;
  };
  if (total > 0) append(std::to_string(static_cast<int>(100.0 * done / total)) + "%");
  append(detail);
  if (lines_) {
    if (!force && secondsBetween(lastLine_, now) < kLineIntervalSeconds) return;
    lastLine_ = now;
    rootShown_ = true;
    append(etaText(done, total));
    std::fprintf(stderr, "progress: %s\n", text.c_str());
    std::fflush(stderr);
    return;
  }
  if (!tty_ || verbosity_ < 0) return;
  if (!force && secondsBetween(lastDraw_, now) < 1.0 / kTerminalRefreshHz) return;
  lastDraw_ = now;
  if (!sub_.empty()) append(std::string(1, '[').append(token(sub_)).append(1, ']'));
  append(etaText(done, total));
  std::fprintf(stderr, "\r\033[K%s", text.c_str());
  std::fflush(stderr);
  lineOpen_ = true;
}

void TerminalSink::progressBegin(const std::string& phase, double total) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (root_.empty()) {
    root_ = phase;
    rootDepth_ = 1;
    rootStart_ = Clock::now();
    rootDone_ = 0;
    rootTotal_ = total;
    rootDetail_.clear();
    rootShown_ = true;
    sub_.clear();
    showLine(root_, 0, total, {}, true);
    return;
  }
  if (phase == root_) ++rootDepth_;
  else {
    ++nested_[phase];
    sub_ = phase;
    showLine(root_, rootDone_, rootTotal_, rootDetail_, false);
  }
}

void TerminalSink::progress(const std::string& phase, double done, double total, const std::string& detail) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (root_.empty()) return;  // no phase begun (or it has ended): nothing to show
  if (phase != root_) {
    if (!nested_.count(phase)) return;  // not open here: ignore
    sub_ = phase;
    showLine(root_, rootDone_, rootTotal_, rootDetail_, false);
    return;
  }
  rootDone_ = done;
  rootTotal_ = total;
  rootDetail_ = detail;
  rootShown_ = false;
  showLine(root_, done, total, detail, false);
}

void TerminalSink::progressEnd(const std::string& phase) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (phase != root_) {
    auto it = nested_.find(phase);
    if (it != nested_.end() && --it->second <= 0) nested_.erase(it);
    if (sub_ == phase && !nested_.count(phase)) sub_.clear();
    return;
  }
  if (--rootDepth_ > 0) return;
  if (lines_) {
    if (!rootShown_) showLine(root_, rootDone_, rootTotal_, rootDetail_, true);  // the final state
    std::fprintf(stderr, "progress: %s done %.2fs\n", token(root_).c_str(), secondsBetween(rootStart_, Clock::now()));
    std::fflush(stderr);
  }
  // on a terminal the line stays until the next phase or message rewrites it
  root_.clear();
  nested_.clear();
  sub_.clear();
}

}  // namespace aniso::cli
