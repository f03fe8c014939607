#include "tools/cli/TerminalSink.h"

#include <unistd.h>

#include <cstdio>

namespace aniso::cli {

TerminalSink::TerminalSink(int verbosity, bool progressLines)
    : verbosity_(verbosity), tty_(::isatty(2) != 0), lines_(progressLines) {}

void TerminalSink::message(LogLevel level, const std::string& text) {
  const int minLevel = verbosity_ < 0 ? 3 : verbosity_ > 0 ? 0 : 2;
  if (static_cast<int>(level) < minLevel) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (lineOpen_) {
    std::fputs("\r\033[K", stderr);
    lineOpen_ = false;
  }
  const char* tag = level == LogLevel::Warning ? "warning: " : level == LogLevel::Error ? "error: " : "";
  std::fprintf(stderr, "anisomesh: %s%s\n", tag, text.c_str());
}

void TerminalSink::progress(const std::string& phase, double done, double total, const std::string& detail) {
  if (lines_) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (total > 0)
      std::fprintf(stderr, "progress: %s %.0f%% %s\n", phase.c_str(), 100.0 * done / total, detail.c_str());
    else
      std::fprintf(stderr, "progress: %s %s\n", phase.c_str(), detail.c_str());
    std::fflush(stderr);
    return;
  }
  if (!tty_ || verbosity_ < 0) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (total > 0)
    std::fprintf(stderr, "\r\033[K%s %3.0f%% %s", phase.c_str(), 100.0 * done / total, detail.c_str());
  else
    std::fprintf(stderr, "\r\033[K%s %.0f %s", phase.c_str(), done, detail.c_str());
  std::fflush(stderr);
  lineOpen_ = true;
}

void TerminalSink::progressEnd(const std::string& phase) {
  if (lines_) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::fprintf(stderr, "progress: %s done\n", phase.c_str());
    std::fflush(stderr);
    return;
  }
  if (!tty_ || verbosity_ < 0) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (lineOpen_) std::fputs("\r\033[K", stderr);
  lineOpen_ = false;
}

}  // namespace aniso::cli
