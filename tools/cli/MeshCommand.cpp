#include <algorithm>
#include <chrono>
#include <filesystem>

#include "io/AtomicFile.h"
#include "io/MeshWriter.h"
#include "io/Report.h"
#include "io/SizingFile.h"
#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"
#include "mesher/core/Log.h"
#include "mesher/pipeline/Pipeline.h"
#include "tools/cli/BudgetReport.h"
#include "tools/cli/Commands.h"
#include "tools/cli/ModelInput.h"
#include "tools/cli/MeshArgsCheck.h"
#include "tools/cli/RunReport.h"
#include "tools/cli/RunSummary.h"
#include "tools/cli/SizingReport.h"

namespace aniso::cli {
namespace {

/// Options that are wrong whatever the model: exit 2 before any work.
void checkArguments(const MeshArgs& a) {
  checkMeshArguments(a);
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

/// The problem a one-line message names: the first failed one, else the first degraded one.
const Problem* firstShortcoming(const io::Report& r) {
  const Problem* p = firstOf(r.problems, Severity::Failed);
  return p ? p : firstOf(r.problems, Severity::Degraded);
}

/// A meshing failure: the report (status failed, the total time) is written, no mesh, and
/// the first failure becomes the one-line error (exit 3).
[[noreturn]] void failRun(const MeshArgs& a, io::Report& r, std::chrono::steady_clock::time_point t0,
                          const std::string& prefix = {}) {
  r.status = io::RunStatus::Failed;
  r.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  writeReport(a, r);
  const Problem* p = firstShortcoming(r);
  throw MeshingError(a.file + ": " + prefix + (p ? entityLabel(p->entity) + ": " + p->detail : std::string("nothing could be meshed")));
}

/// The run's grade from its problems (mesher/core/Problem.h) once a mesh is written; a
/// degraded run says so on the terminal, naming the first shortcomings.
void finishRun(const MeshArgs& a, io::Report& r, std::chrono::steady_clock::time_point t0) {
  r.status = gradeRun(r.problems, true);
  r.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  writeReport(a, r);
  if (r.status != io::RunStatus::Degraded) return;
  int failed = 0, degraded = 0;
  for (const Problem& p : r.problems) {
    failed += p.severity == Severity::Failed;
    degraded += p.severity == Severity::Degraded;
  }
  std::string text = a.file + ": the mesh is degraded: ";
  if (failed) text += std::to_string(failed) + " entit" + (failed == 1 ? "y" : "ies") + " left out";
  if (failed && degraded) text += ", ";
  if (degraded) text += std::to_string(degraded) + " meshed with shortcomings";
  const Problem* p = firstShortcoming(r);
  text += "; first: " + entityLabel(p->entity) + ": " + p->detail;
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

/// Reads the model, meshes it (mesher/pipeline/Pipeline.h), writes the mesh and the report.
static int meshRun(const MeshArgs& given, io::Report& report) {
  MeshArgs args = given;
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  checkArguments(args);
  // The sizing file is read (and checked) before the model, so a bad one fails fast.
  MeshRequest request;
  if (!args.options.sizingFile.empty()) request.user = io::readSizingFile(args.options.sizingFile);
  report.input = args.file;
  report.options = optionsJson(args);

  // Reading and preparing the model: failures here are bad input (exit 2).
  ModelInput in = loadModel(args.file, args.fragment, args.overlaps, args.options.cancel.get());
  checkCancel(args.options.cancel.get(), "reading");
  report.times = in.times;
  report.extra["model"] = in.summary;
  report.problems.insert(report.problems.end(), in.problems.begin(), in.problems.end());
  if (args.extraSizing) report.extra["adapt"] = args.extraSizing(in.model, request.user);
  const int dim = args.options.dim == 0 ? defaultDimension(args, in.solids) : resolvedDim(args.options, in.solids > 0);
  if (dim == 3 && in.solids == 0)
    throw InputError(args.file + (in.analytic ? ": nothing to mesh in 3D: an analytic model is a surface (use --dim 2)"
                                              : ": nothing to mesh in 3D: the model has no solids (use --dim 2)"));
  if (in.model.faces.empty()) throw InputError(args.file + ": nothing to mesh: the model has no faces");
  report.options["dim"] = dim;
  if (dim == 3 && !args.anisotropyGiven) {  // see MeshArgs::anisotropyGiven
    args.options.sizing.anisotropy = 1;
    report.options["anisotropy"] = 1.0;
  }
  args.options.maxElements = report.options["max_elements"] = elementBudget(args.options.maxElements, dim);
  args.options.dim = dim;
  request.options = args.options;
  const std::unique_ptr<ControlSpace2d> analytic = analyticControlSpace(in);
  request.analytic = analytic.get();

  const MeshResult result = meshModel(in.model, request);
  fillRunReport(in.model, result, report);
  report.extra["sizing"] = sizingReport(args.options.sizing, in.model.diagonal(), result.surface.mesh,
                                        result.volumeRan ? &result.volume.mesh : nullptr);
  if (result.stop == PipelineStop::Model) failRun(args, report, t0, "invalid model topology: ");
  if (!result.meshed()) failRun(args, report, t0);
  io::WriteOptions wopt;
  wopt.binary = args.binary;
  wopt.mshVersion = args.mshVersion;
  const auto tw = Clock::now();
  if (result.volumeRan) io::writeVolumeMesh(in.model, result.volume.mesh, args.output, wopt);
  else io::writeSurfaceMesh(in.model, result.surface.mesh, args.output, wopt);
  report.times.emplace_back("write", std::chrono::duration<double>(Clock::now() - tw).count());
  finishRun(args, report, t0);
  return 0;
}

/// --time-limit: the token every mesher checks (mesher/core/Cancel.h); when it fires, the
/// report says failed, no mesh is written, and the one line names the phase (exit 3).
int runMesh(const MeshArgs& given) {
  const auto t0 = std::chrono::steady_clock::now();
  MeshArgs args = given;
  if (args.timeLimit > 0) args.options.cancel = std::make_shared<const CancelToken>(args.timeLimit);
  io::Report report;
  try {
    const int rc = meshRun(args, report);
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

}  // namespace aniso::cli
