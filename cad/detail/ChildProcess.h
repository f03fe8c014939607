#pragma once
// Internal: OCCT work run in a forked child process, so that a crash of the kernel (a
// SIGSEGV in a reader, in ShapeFix, in the general fuse) ends the child, never us.
//
// runInChild(impl, work) forks; the child runs work(impl) on its copy of impl and writes
// the resulting shape (binary BREP, exact) with its part names and colours, its face tags
// (STEP face names and colours) and work's returned payload
// to a private temporary folder; the parent reads them back into impl. Turning the signal
// into an exception in-process (OSD::SetSignal, OCC_CATCH_SIGNALS: a longjmp out of the
// middle of OCCT) could leave the heap inconsistent for the rest of the run, which is why
// the work runs in a process that is thrown away. Cost: one fork (copy-on-write) and one
// binary BREP write + read of a changed shape, not noticeable next to the work itself
// (docs/measurements.md). The child's stdout and stderr go to /dev/null.
//
// A shape crosses the boundary exactly but for round-off: BinTools rebuilds transformations
// and axes from their stored values (gp_Trsf::SetValues divides by det^(1/3), gp_Dir
// normalises), so a tilted or rotated part may move by an ulp (docs/measurements.md).
// Counts, names and topology are unchanged.
//
// Outcome:
//   Done     impl holds the child's shape and names; `payload` what work returned.
//   Input    work threw InputError: `message` is its text; impl unchanged.
//   Failed   work threw anything else (Standard_Failure, MeshingError, std::exception).
//   Crashed  the child was killed by a signal (`message`: "signal 11 (Segmentation fault)").
// When no process can be started (fork fails), the work runs in this process with a
// warning, and impl is restored when it fails.
#include <functional>
#include <string>

#include "cad/detail/CadModelImpl.h"

namespace aniso::cad::detail {

struct ChildOutcome {
  enum Kind { Done, Input, Failed, Crashed } kind = Failed;
  std::string message;
  std::string payload;
  bool ok() const { return kind == Done; }
};

/// With impl.cancel set, the child is killed when the token stops the run, and Cancelled
/// (mesher/core/Cancel.h) is thrown naming `phase`.
ChildOutcome runInChild(CadModel::Impl& impl, const char* phase,
                        const std::function<std::string(CadModel::Impl&)>& work);

/// Test hook: true when the environment variable ANISOMESH_TEST_CRASH lists `point`
/// (comma-separated, e.g. "reader-xcaf,prepare-fix"). The points are named where they are
/// used; each raises SIGSEGV there, so that the recovery from a kernel crash is tested
/// without a model that crashes OCCT. "fork-fails" makes runInChild find no process.
bool testCrashRequested(const char* point);
/// Raises SIGSEGV when testCrashRequested(point).
void testCrashPoint(const char* point);

}  // namespace aniso::cad::detail
