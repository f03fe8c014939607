#include <algorithm>
#include <chrono>
#include <filesystem>

#include "io/AtomicFile.h"
#include "io/MeshWriter.h"
#include "io/Report.h"
#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"
#include "mesher/core/Log.h"
#include "tools/app/MeshArgsCheck.h"
#include "tools/app/MeshRun.h"
#include "tools/cli/Commands.h"
#include "tools/cli/RunSummary.h"

namespace aniso::cli {
namespace {

/// Options that are wrong whatever the model: exit 2 before any work.
void checkArguments(const MeshArgs& a) {
  app::checkMeshArguments(a);
  if (!isKnownOutputExtension(a.output))
    throw InputError(a.output + ": unknown output format (expected .msh .inp .vtu .stl .obj .off .unv)");
  const std::string bad = a.options.sizing.check();
  if (!bad.empty()) throw InputError(a.file + ": " + bad);
  const auto dir = std::filesystem::path(a.output).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw InputError(a.output + ": output folder does not exist");
}

void writeReport(const MeshArgs& a, const io::Report& r) {
  if (a.report.empty()) return;
  io::writeFileAtomically(a.report, r.toJson().dump(1) + "\n");
}

/// A meshing failure: the report (status failed, the total time) is written, no mesh, and
/// the first failure becomes the one-line error (exit 3).
[[noreturn]] void failRun(const MeshArgs& a, io::Report& r, std::chrono::steady_clock::time_point t0, PipelineStop stop) {
  r.status = io::RunStatus::Failed;
  r.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  writeReport(a, r);
  throw MeshingError(app::failureMessage(a.file, r, stop));
}

/// The run's grade from its problems (mesher/core/Problem.h) once a mesh is written; a
/// degraded run says so on the terminal, naming the first shortcomings.
void finishRun(const MeshArgs& a, io::Report& r, std::chrono::steady_clock::time_point t0) {
  r.status = gradeRun(r.problems, true);
  r.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  writeReport(a, r);
  if (r.status != io::RunStatus::Degraded) return;
  std::string text = a.file + ": the mesh is degraded: " + app::degradedSummary(r);
  if (a.report.empty()) text += " (--report FILE.json lists them all)";
  else text += " (all in " + a.report + ")";
  logWarning(text);
}

}  // namespace

bool isKnownOutputExtension(const std::string& path) {
  static const char* known[] = {".msh", ".inp", ".vtu", ".stl", ".obj", ".off", ".unv"};
  const std::string ext = lowerExtension(path);
  return std::any_of(std::begin(known), std::end(known), [&](const char* k) { return ext == k; });
}

int writeRun(const MeshArgs& args, const Model& model, const MeshResult& result, io::Report& report,
             std::chrono::steady_clock::time_point t0, const std::vector<io::NodeData>& nodeData) {
  using Clock = std::chrono::steady_clock;
  if (!result.meshed()) failRun(args, report, t0, result.stop);
  io::WriteOptions wopt;
  wopt.binary = args.binary;
  wopt.mshVersion = args.mshVersion;
  wopt.nodeData = nodeData;
  const auto tw = Clock::now();
  if (result.volumeRan) io::writeVolumeMesh(model, result.volume.mesh, args.output, wopt);
  else io::writeSurfaceMesh(model, result.surface.mesh, args.output, wopt);
  report.times.emplace_back("write", std::chrono::duration<double>(Clock::now() - tw).count());
  finishRun(args, report, t0);
  return 0;
}

/// --time-limit: the token every mesher checks (mesher/core/Cancel.h); when it fires, the
/// report says failed, no mesh is written, and the one line names the phase (exit 3).
int runGuarded(const MeshArgs& given, const std::function<int(MeshArgs&, io::Report&)>& body) {
  const auto t0 = std::chrono::steady_clock::now();
  MeshArgs args = given;
  if (args.timeLimit > 0) args.options.cancel = std::make_shared<const CancelToken>(args.timeLimit);
  io::Report report;
  try {
    checkArguments(args);
    const int rc = body(args, report);
    printRunSummary(report, args.output);
    return rc;
  } catch (const Cancelled& e) {
    report.problems.push_back({EntityRef::model(), Severity::Failed, "time-limit", e.what(), "run"});
    report.status = io::RunStatus::Failed;
    report.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    writeReport(args, report);
    throw MeshingError(args.file + ": " + e.what());
  }
}

int runMesh(const MeshArgs& given) {
  return runGuarded(given, [](MeshArgs& args, io::Report& report) {
    const auto t0 = std::chrono::steady_clock::now();
    const app::MeshRun run = app::meshFile(args, report);
    return writeRun(args, run.input.model, run.result, report, t0, {});
  });
}

}  // namespace aniso::cli
