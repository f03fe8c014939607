#include "tools/python/Worker.h"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include "mesher/core/Log.h"

namespace aniso::python {
namespace py = pybind11;
namespace {

struct Event {
  enum class Kind { Message, Progress, End } kind = Kind::Message;
  LogLevel level = LogLevel::Info;
  std::string phase, text;
  double done = 0, total = 0;
};

/// The library's messages and progress, queued for the Python thread.
class QueueSink : public LogSink {
 public:
  void message(LogLevel level, const std::string& text) override { push({Event::Kind::Message, level, {}, text}); }
  void progress(const std::string& phase, double done, double total, const std::string& detail) override {
    push({Event::Kind::Progress, LogLevel::Info, phase, detail, done, total});
  }
  void progressBegin(const std::string& phase, double total) override {
    std::lock_guard<std::mutex> lock(mutex_);
    totals_.emplace_back(phase, total);
    events_.push_back({Event::Kind::Progress, LogLevel::Info, phase, {}, 0, total});
    ready_.notify_all();
  }
  void progressEnd(const std::string& phase) override {
    std::lock_guard<std::mutex> lock(mutex_);
    double total = 0;
    for (auto it = totals_.rbegin(); it != totals_.rend(); ++it)
      if (it->first == phase) {
        total = it->second;
        totals_.erase(std::next(it).base());
        break;
      }
    events_.push_back({Event::Kind::End, LogLevel::Info, phase, "end", total, total});
    ready_.notify_all();
  }
  void finish() {
    std::lock_guard<std::mutex> lock(mutex_);
    finished_ = true;
    ready_.notify_all();
  }
  /// Waits up to `wait` for an event or the end of the job; `finished` true once the job
  /// has ended and every event was taken.
  std::deque<Event> take(std::chrono::milliseconds wait, bool& finished) {
    std::unique_lock<std::mutex> lock(mutex_);
    ready_.wait_for(lock, wait, [&] { return finished_ || !events_.empty(); });
    std::deque<Event> out;
    out.swap(events_);
    finished = finished_;
    return out;
  }

 private:
  void push(Event e) {
    std::lock_guard<std::mutex> lock(mutex_);
    events_.push_back(std::move(e));
    ready_.notify_all();
  }
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<Event> events_;
  std::deque<std::pair<std::string, double>> totals_;  ///< open phases and their totals
  bool finished_ = false;
};

int pythonLevel(LogLevel l) {
  switch (l) {
    case LogLevel::Debug: return 10;
    case LogLevel::Info:
    case LogLevel::Notice: return 20;
    case LogLevel::Warning: return 30;
    case LogLevel::Error: return 40;
  }
  return 20;
}

/// Hands one event to Python (GIL held); a Python exception propagates.
void deliver(const Event& e, const py::object& logger, const py::object& progress) {
  if (e.kind == Event::Kind::Message) {
    const int level = pythonLevel(e.level);
    if (logger.attr("isEnabledFor")(level).cast<bool>()) logger.attr("log")(level, "%s", e.text);
  } else if (!progress.is_none()) {
    progress(e.phase, e.done, e.total, e.text);
  }
}

/// The sink installed for one call, the previous one put back at the end.
class SinkScope {
 public:
  explicit SinkScope(std::shared_ptr<LogSink> sink) : previous_(setLogSink(std::move(sink))) {}
  ~SinkScope() { setLogSink(previous_); }
  SinkScope(const SinkScope&) = delete;
  SinkScope& operator=(const SinkScope&) = delete;

 private:
  std::shared_ptr<LogSink> previous_;
};

std::mutex& serialMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

void runInWorker(const std::function<void()>& job, const CancelToken& cancel, const py::object& progress) {
  std::unique_lock<std::mutex> serial(serialMutex(), std::defer_lock);
  {
    py::gil_scoped_release release;
    serial.lock();
  }
  const py::object logger = py::module_::import("logging").attr("getLogger")("anisomesh");
  auto sink = std::make_shared<QueueSink>();
  const SinkScope scope(sink);
  std::exception_ptr failure;
  std::thread worker([&] {
    try {
      job();
    } catch (...) {
      failure = std::current_exception();
    }
    sink->finish();
  });
  std::optional<py::error_already_set> pyError;  // the first Python exception (Ctrl-C, progress)
  auto stop = [&](py::error_already_set&& e) {
    if (!pyError) pyError.emplace(std::move(e));
    cancel.request();
  };
  try {
    for (bool finished = false; !finished;) {
      std::deque<Event> events;
      {
        py::gil_scoped_release release;
        events = sink->take(std::chrono::milliseconds(50), finished);
      }
      for (const Event& e : events) {
        if (pyError) break;  // stopping: the caller no longer listens
        try {
          deliver(e, logger, progress);
        } catch (py::error_already_set& err) {
          stop(std::move(err));
        }
      }
      if (!pyError && PyErr_CheckSignals() != 0) stop(py::error_already_set());
    }
  } catch (...) {  // e.g. out of memory in the Python thread: the worker is stopped and joined
    cancel.request();
    py::gil_scoped_release release;
    worker.join();
    throw;
  }
  {
    py::gil_scoped_release release;
    worker.join();
  }
  if (pyError) throw *pyError;
  if (failure) std::rethrow_exception(failure);
}

}  // namespace aniso::python
