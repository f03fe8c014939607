#include <chrono>
#include <cstdio>
#include <sstream>
#include <vector>

#include "cad/detail/ChildProcess.h"
#include "cad/detail/Prepare.h"
#include "mesher/core/Error.h"
#include "mesher/core/Log.h"

namespace aniso::cad::detail {
namespace {

// The report crosses the process boundary as text: numbers space-separated, strings
// length-prefixed. Every field of PrepareReport must be here (CadModel.h says so); the size
// check makes a new field a build error here instead of a field silently lost.
static_assert(sizeof(PrepareReport) == 2 * sizeof(int) + 2 * sizeof(double) + 3 * sizeof(std::vector<int>),
              "PrepareReport changed: add the new field to encode() and decode()");
std::string encode(const PrepareReport& r) {
  std::ostringstream out;
  out.precision(17);
  out << r.facesSewn << ' ' << r.sharedFaces << ' ' << r.fuzzyValue << ' ' << r.overlaps.size();
  for (const Overlap& o : r.overlaps)
    out << ' ' << o.a << ' ' << o.b << ' ' << o.volume << ' ' << o.assignedTo << ' ' << o.nameA.size() << ':' << o.nameA
        << ' ' << o.nameB.size() << ':' << o.nameB;
  out << ' ' << r.unfusedSolids.size();
  for (const int id : r.unfusedSolids) out << ' ' << id;
  out << ' ' << r.selfOverlapVolume;
  out << ' ' << r.warnings.size();
  for (const std::string& w : r.warnings) out << ' ' << w.size() << ':' << w;
  return out.str();
}

PrepareReport decode(const std::string& text) {
  std::istringstream in(text);
  PrepareReport r;
  size_t n = 0;
  const auto readString = [&in](std::string& w) {
    size_t len = 0;
    char colon = 0;
    in >> len >> colon;
    w.resize(len);
    in.read(w.data(), static_cast<std::streamsize>(len));
  };
  in >> r.facesSewn >> r.sharedFaces >> r.fuzzyValue >> n;
  r.overlaps.resize(n);
  for (Overlap& o : r.overlaps) {
    in >> o.a >> o.b >> o.volume >> o.assignedTo;
    readString(o.nameA);
    readString(o.nameB);
  }
  in >> n;
  r.unfusedSolids.resize(n);
  for (int& id : r.unfusedSolids) in >> id;
  in >> r.selfOverlapVolume;
  in >> n;
  r.warnings.resize(n);
  for (std::string& w : r.warnings) readString(w);
  if (!in) throw MeshingError("the preparation report of the child process is corrupt");
  return r;
}

}  // namespace

void runPrepareStep(const char* step, const char* crashPoint, CadModel::Impl& impl, PrepareReport& report,
                    const std::function<void(CadModel::Impl&, PrepareReport&)>& run) {
  // the child starts from copies of impl and report, and sends both back
  const auto t0 = std::chrono::steady_clock::now();
  const ChildOutcome o = runInChild(impl, step, [&](CadModel::Impl& i) {
    testCrashPoint(crashPoint);
    run(i, report);
    return encode(report);
  });
  char took[64];
  std::snprintf(took, sizeof took, ": %.2f s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  logDebug(std::string("preparation, ") + step + took);
  if (o.kind == ChildOutcome::Done) {
    report = decode(o.payload);
    return;
  }
  if (o.kind == ChildOutcome::Input) throw InputError(o.message);  // e.g. --overlaps error
  report.warnings.push_back(std::string(step) + (o.kind == ChildOutcome::Crashed ? " crashed in OpenCASCADE (" : " failed (") +
                            o.message + "); the shape is kept as it was before it");
}

}  // namespace aniso::cad::detail
