#pragma once
// runInWorker — a long C++ job (a mesh run, a write) in a worker thread while the calling
// Python thread waits with the GIL released. Every 50 ms, and whenever the library logs or
// reports progress (mesher/core/Log.h, captured by a sink installed for the call), the
// calling thread takes the GIL back, passes the messages to Python's `logging` (logger
// "anisomesh": Debug → DEBUG, Info and Notice → INFO, Warning, Error) and the progress to
// `progress(phase, done, total, detail)` (begin: done 0; end: done = total, detail "end"),
// and checks for signals. A KeyboardInterrupt (Ctrl-C) or an exception raised by `progress`
// requests `cancel` (mesher/core/Cancel.h): the job stops at its next check, is joined,
// and that Python exception is raised. Otherwise an exception of the job is rethrown after
// the join. Calls are serialized, since the library's log sink is process-wide.
#include <pybind11/pybind11.h>

#include <functional>

#include "mesher/core/Cancel.h"

namespace aniso::python {

/// `progress` may be None. `job` must not touch Python objects.
void runInWorker(const std::function<void()>& job, const CancelToken& cancel, const pybind11::object& progress);

}  // namespace aniso::python
