#pragma once
// The CLI's LogSink: warnings and errors on stderr, notices (the run's summary) unless -q,
// info with -v. Progress (mesher/core/Log.h) is shown per top-level phase: a phase begun
// while another is open is folded into it (the volume's hundreds of Delaunay 3D runs show
// as "volume"). Phase names are printed with spaces as '_', so that a line splits on spaces.
//  - on a terminal (not -q): one line, rewritten at most kTerminalRefreshHz times a second,
//    "PHASE PERCENT% DETAIL [sub-phase] eta Ns"; a message replaces it (the summary at the end);
//  - with progressLines (--progress, for a program reading the pipe), whatever stderr is:
//      progress: PHASE PERCENT% DETAIL      when a top-level phase starts (0%), then at most
//                                           once a second, and its last state before it ends
//                                           (PERCENT omitted when the total is unknown)
//      progress: PHASE done SECONDSs        when it ends
#include <chrono>
#include <map>
#include <mutex>
#include <string>

#include "mesher/core/Log.h"

namespace aniso::cli {

class TerminalSink : public LogSink {
 public:
  /// verbosity: -1 quiet, 0 normal, 1 verbose.
  explicit TerminalSink(int verbosity, bool progressLines = false);
  void message(LogLevel level, const std::string& text) override;
  void progressBegin(const std::string& phase, double total) override;
  void progress(const std::string& phase, double done, double total, const std::string& detail) override;
  void progressEnd(const std::string& phase) override;

 private:
  using Clock = std::chrono::steady_clock;
  /// One line per top-level phase and second in --progress mode.
  static constexpr double kLineIntervalSeconds = 1.0;
  /// Rewrites of the terminal line per second.
  static constexpr double kTerminalRefreshHz = 10.0;
  /// The ETA is shown from this share of the work and this many seconds on (before, a
  /// guess from too little).
  static constexpr double kEtaMinFraction = 0.05, kEtaMinSeconds = 2.0;

  void showLine(const std::string& phase, double done, double total, const std::string& detail, bool force);
  std::string etaText(double done, double total) const;

  int verbosity_;
  bool tty_;
  bool lines_;
  bool lineOpen_ = false;
  std::string root_;                ///< the open top-level phase, "" when none
  int rootDepth_ = 0;               ///< open instances of root_'s name (it may nest in itself)
  std::map<std::string, int> nested_;  ///< open nested phases by name
  std::string sub_;                 ///< the latest nested phase, for the terminal line
  Clock::time_point rootStart_{}, lastLine_{}, lastDraw_{};
  double rootDone_ = 0, rootTotal_ = 0;
  std::string rootDetail_;
  bool rootShown_ = true;  ///< the root's latest state has been printed (--progress)
  std::mutex mutex_;
};

}  // namespace aniso::cli
