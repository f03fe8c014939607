#pragma once
// The CLI's LogSink: warnings and errors on stderr, info with -v, nothing with -q; a
// progress line on stderr only when stderr is a terminal (quiet in pipes and CI), or, with
// progressLines (--progress), one line per update for a program reading the pipe:
//   progress: PHASE PERCENT% DETAIL      (PERCENT omitted when the total is unknown)
//   progress: PHASE done
#include <mutex>

#include "mesher/core/Log.h"

namespace aniso::cli {

class TerminalSink : public LogSink {
 public:
  /// verbosity: -1 quiet, 0 normal, 1 verbose.
  explicit TerminalSink(int verbosity, bool progressLines = false);
  void message(LogLevel level, const std::string& text) override;
  void progress(const std::string& phase, double done, double total, const std::string& detail) override;
  void progressEnd(const std::string& phase) override;

 private:
  int verbosity_;
  bool tty_;
  bool lines_;
  bool lineOpen_ = false;
  std::mutex mutex_;
};

}  // namespace aniso::cli
