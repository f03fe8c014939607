#include "tools/app/MeshRun.h"

#include <memory>

#include "io/SizingFile.h"
#include "mesher/core/Error.h"
#include "mesher/pipeline/Pipeline.h"
#include "tools/app/BudgetReport.h"
#include "tools/app/MeshArgsCheck.h"
#include "tools/app/RunReport.h"
#include "tools/app/SizingReport.h"

namespace aniso::app {
namespace {

/// The first failed problem, else the first degraded one.
const Problem* firstShortcoming(const io::Report& r) {
  const Problem* p = firstOf(r.problems, Severity::Failed);
  return p ? p : firstOf(r.problems, Severity::Degraded);
}

}  // namespace

PreparedRun prepareRun(MeshArgs& args, io::Report& report) {
  checkMeshArguments(args);
  const std::string bad = args.options.sizing.check();
  if (!bad.empty()) throw InputError(args.file + ": " + bad);
  // The sizing file is read (and checked) before the model, so a bad one fails fast.
  PreparedRun run;
  MeshRequest& request = run.request;
  if (!args.options.sizingFile.empty()) request.user = io::readSizingFile(args.options.sizingFile);
  report.input = args.file;
  report.options = optionsJson(args);

  // Reading and preparing the model: failures here are bad input (exit 2).
  run.input = loadModel(args.file, args.fragment, args.overlaps, args.options.cancel.get());
  ModelInput& in = run.input;
  checkCancel(args.options.cancel.get(), "reading");
  report.times = in.times;
  report.extra["model"] = in.summary;
  report.problems.insert(report.problems.end(), in.problems.begin(), in.problems.end());
  const int dim = args.options.dim == 0 ? defaultDimension(args, in.solids) : resolvedDim(args.options, in.solids > 0);
  if (dim == 3 && in.solids == 0)
    throw InputError(args.file + (in.analytic ? ": nothing to mesh in 3D: an analytic model is a surface (use --dim 2)"
                                              : ": nothing to mesh in 3D: the model has no solids (use --dim 2)"));
  if (in.model.faces.empty()) throw InputError(args.file + ": nothing to mesh: the model has no faces");
  report.options["dim"] = dim;
  if (!args.anisotropyGiven) {  // see MeshArgs::anisotropyGiven
    args.options.sizing.anisotropy = 1;
    report.options["anisotropy"] = 1.0;
  }
  args.options.maxElements = report.options["max_elements"] = elementBudget(args.options.maxElements, dim);
  args.options.dim = dim;
  request.options = args.options;
  run.analytic = analyticControlSpace(in);
  request.analytic = run.analytic.get();
  return run;
}

void reportResult(const MeshArgs& args, const Model& model, const MeshResult& result, io::Report& report) {
  fillRunReport(model, result, report);
  report.extra["sizing"] = sizingReport(args.options.sizing, model.diagonal(), result.surface.mesh,
                                        result.volumeRan ? &result.volume.mesh : nullptr);
}

MeshRun meshFile(MeshArgs& args, io::Report& report) {
  PreparedRun prepared = prepareRun(args, report);
  MeshRun run;
  run.result = meshModel(prepared.input.model, prepared.request);
  run.input = std::move(prepared.input);
  reportResult(args, run.input.model, run.result, report);
  return run;
}

std::string failureMessage(const std::string& file, const io::Report& r, PipelineStop stop) {
  const std::string prefix = stop == PipelineStop::Model ? "invalid model topology: " : "";
  const Problem* p = firstShortcoming(r);
  return file + ": " + prefix + (p ? entityLabel(p->entity) + ": " + p->detail : std::string("nothing could be meshed"));
}

std::string degradedSummary(const io::Report& r) {
  int failed = 0, degraded = 0;
  for (const Problem& p : r.problems) {
    failed += p.severity == Severity::Failed;
    degraded += p.severity == Severity::Degraded;
  }
  std::string text;
  if (failed) text += std::to_string(failed) + " entit" + (failed == 1 ? "y" : "ies") + " left out";
  if (failed && degraded) text += ", ";
  if (degraded) text += std::to_string(degraded) + " meshed with shortcomings";
  const Problem* p = firstShortcoming(r);
  if (p) text += "; first: " + entityLabel(p->entity) + ": " + p->detail;
  return text;
}

}  // namespace aniso::app
