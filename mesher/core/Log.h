#pragma once
// The one logging and progress facade of the library (STYLE.md §11). Library code never
// writes to stdout or stderr: it calls log() and Progress, and the program that links the
// library installs a LogSink deciding what reaches the terminal. Without a sink, nothing
// is printed. Thread-safe.
#include <atomic>
#include <memory>
#include <string>

namespace aniso {

/// Info: details (-v); Notice: what a run tells its user at the end (its summary), shown
/// unless quiet; Warning and Error always but Warning not when quiet.
enum class LogLevel { Debug = 0, Info = 1, Notice = 2, Warning = 3, Error = 4 };

class LogSink {
 public:
  virtual ~LogSink() = default;
  virtual void message(LogLevel level, const std::string& text) = 0;
  /// A long phase reports progress: done of total units (total 0 = unknown), with an
  /// optional detail (e.g. the predicted final element count).
  virtual void progress(const std::string& phase, double done, double total, const std::string& detail) = 0;
  /// A phase starts (a Progress is made). Phases may nest (a phase started while another is
  /// open runs inside it) and run concurrently on several threads; each begin has one end.
  virtual void progressBegin(const std::string& phase, double total) { progress(phase, 0, total, {}); }
  /// The phase is over (clear a progress line).
  virtual void progressEnd(const std::string& phase) = 0;
};

/// Installs the process-wide sink (nullptr: silence). Returns the previous one.
std::shared_ptr<LogSink> setLogSink(std::shared_ptr<LogSink> sink);

void log(LogLevel level, const std::string& text);
inline void logInfo(const std::string& t) { log(LogLevel::Info, t); }
inline void logNotice(const std::string& t) { log(LogLevel::Notice, t); }
inline void logWarning(const std::string& t) { log(LogLevel::Warning, t); }
inline void logDebug(const std::string& t) { log(LogLevel::Debug, t); }

/// A phase with progress: construct at the start, update() as work is done; the
/// destructor ends it. Updates are rate-limited so that hot loops may call update() often,
/// and update() may be called from any thread (the sink serializes its output).
class Progress {
 public:
  Progress(std::string phase, double total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  /// Reports done (of the total) with an optional detail; at most 10 times per second
  /// unless `force` (e.g. the final state of a phase).
  void update(double done, const std::string& detail = {}, bool force = false);

 private:
  std::string phase_;
  double total_;
  std::atomic<long long> lastNs_{0};
};

}  // namespace aniso
