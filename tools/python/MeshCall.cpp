#include "tools/python/MeshCall.h"

#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <map>
#include <optional>

#include "mesher/core/Error.h"
#include "tools/app/AdaptRun.h"
#include "tools/app/InfoJson.h"
#include "tools/app/MeshRun.h"
#include "tools/python/MeshObject.h"
#include "tools/python/PyJson.h"
#include "tools/python/Worker.h"

namespace aniso::python {
namespace py = pybind11;
namespace {

py::handle gError, gInputError, gMeshingError;  // owned by the module

/// Sets `type(message)` with .problems and .report as the Python error.
void setError(py::handle type, const std::string& message, py::object problems, py::object report) {
  py::object e = type(message);
  e.attr("problems") = std::move(problems);
  e.attr("report") = std::move(report);
  PyErr_SetObject(type.ptr(), e.ptr());
}

[[noreturn]] void raise(py::handle type, const std::string& message, py::object problems, py::object report) {
  setError(type, message, std::move(problems), std::move(report));
  throw py::error_already_set();
}

[[noreturn]] void refuse(const std::string& message) { raise(gInputError, message, py::list(), py::none()); }

std::string pathOf(const py::object& path) { return py::str(py::module_::import("os").attr("fspath")(path)); }

template <class T>
T choice(const std::string& name, const std::string& value, const std::map<std::string, T>& allowed) {
  const auto it = allowed.find(value);
  if (it != allowed.end()) return it->second;
  std::string names;
  for (const auto& [k, v] : allowed) names += (names.empty() ? "'" : ", '") + k + "'";
  refuse(name + " must be one of " + names + ", not '" + value + "'");
}

cad::OverlapPolicy overlapPolicy(const std::string& s) {
  return choice<cad::OverlapPolicy>(
      "overlaps", s, {{"merge", cad::OverlapPolicy::Merge}, {"keep", cad::OverlapPolicy::Keep}, {"error", cad::OverlapPolicy::Error}});
}

/// The size keywords as the CLI's SizeOptions (tools/cli/SizeOptions.cpp) take them: the
/// same conflicts refused, in the keywords' names.
struct SizeKeywords {
  std::optional<double> size, hmax, hmin, hmaxRel, hminRel, elementsPerCircle, curvatureRatio, gradation, anisotropy,
      contourAnisotropy, chordDeviationRel;
  bool curvature = true;

  void apply(SizingParameters& s) const {
    auto both = [](const auto& a, const auto& b) { return a.has_value() && b.has_value(); };
    if (both(size, hmax)) refuse("size and hmax both set the largest size: give one of them");
    if (both(hmax, hmaxRel) || both(size, hmaxRel)) refuse("hmax_rel and size or hmax both set the largest size: give one of them");
    if (both(hmin, hminRel)) refuse("hmin and hmin_rel both set the smallest size: give one of them");
    if (both(elementsPerCircle, curvatureRatio))
      refuse("elements_per_circle and curvature_ratio both set the curvature (ratio = 2π / elements): give one of them");
    if (!curvature && (elementsPerCircle || curvatureRatio))
      refuse("curvature=False turns the curvature off: drop elements_per_circle / curvature_ratio");
    if (elementsPerCircle && !(std::isfinite(*elementsPerCircle) && *elementsPerCircle >= 1 && *elementsPerCircle <= 1e4))
      refuse("elements_per_circle must be a number from 1 to 10000");
    s.size = size;
    s.hmax = hmax;
    s.hmin = hmin;
    if (hmaxRel) s.hmaxRel = *hmaxRel;
    if (hminRel) s.hminRel = *hminRel;
    if (curvatureRatio) s.curvatureRatio = *curvatureRatio;
    if (elementsPerCircle) s.curvatureRatio = curvatureRatioForElementsPerCircle(*elementsPerCircle);
    if (gradation) s.gradation = *gradation;
    if (anisotropy) s.anisotropy = *anisotropy;
    if (contourAnisotropy) s.contourAnisotropy = *contourAnisotropy;
    if (chordDeviationRel) s.chordDeviationRel = *chordDeviationRel;
    s.curvature = curvature;
  }
};

/// The CLI's MeshArgs of the keywords (main.cpp's defaults).
app::MeshArgs meshArgs(const std::string& file, std::optional<int> dim, int order, bool quad, const std::string& quadMethod,
                       const SizeKeywords& sizes, const std::optional<std::string>& sizing, int threads,
                       std::optional<double> maxElements, bool fragment, const std::string& overlaps,
                       const std::string& internalFaces) {
  app::MeshArgs a;
  a.file = file;
  a.options.sizing = SizingParameters::forAnalysis();
  if (dim && *dim != 2 && *dim != 3) refuse("dim must be 2, 3 or None");
  if (order != 1 && order != 2) refuse("order must be 1 or 2");
  if (threads < 0 || threads > 4096) refuse("threads must be from 0 (all cores) to 4096");
  if (maxElements && !(*maxElements > 0)) refuse("max_elements must be positive");
  a.options.dim = dim.value_or(0);
  a.options.order = order;
  a.options.quad = quad;
  a.options.quadMethod =
      choice<QuadMethod>("quad_method", quadMethod, {{"merge", QuadMethod::Merge}, {"morph", QuadMethod::Morph}, {"mixed", QuadMethod::Mixed}});
  sizes.apply(a.options.sizing);
  a.anisotropyGiven = sizes.anisotropy.has_value();
  if (sizing) a.options.sizingFile = *sizing;
  a.options.threads = threads;
  a.options.maxElements = maxElements.value_or(0);
  a.fragment = fragment;
  a.overlaps = overlapPolicy(overlaps);
  a.options.internalFaces = choice<InternalFaces>(
      "internal_faces", internalFaces, {{"auto", InternalFaces::Auto}, {"crack", InternalFaces::Crack}, {"bond", InternalFaces::Bond}});
  return a;
}

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Runs `job` (which fills `report`) in a worker; errors become the Python exceptions
/// (a time limit as the CLI's runMesh reports it).
void runJob(const app::MeshArgs& args, io::Report& report, std::chrono::steady_clock::time_point t0,
            const py::object& progress, const std::function<void()>& job) {
  try {
    runInWorker(job, *args.options.cancel, progress);
  } catch (const InputError& e) {
    refuse(e.what());
  } catch (const Cancelled& e) {  // time_limit, as the CLI's runMesh
    report.problems.push_back({EntityRef::model(), Severity::Failed, "time-limit", e.what(), "run"});
    report.status = io::RunStatus::Failed;
    report.totalSeconds = secondsSince(t0);
    const auto j = report.toJson();
    raise(gMeshingError, args.file + ": " + e.what(), toPython(j["problems"]), toPython(j));
  } catch (const MeshingError& e) {
    const auto j = report.toJson();
    raise(gMeshingError, e.what(), toPython(j["problems"]), toPython(j));
  }
}

/// The anisomesh.Mesh of a run's result, graded; a result with no mesh raises MeshingError.
py::object meshObject(const app::MeshArgs& args, io::Report& report, Model&& model, MeshResult&& result,
                      std::chrono::steady_clock::time_point t0) {
  report.totalSeconds = secondsSince(t0);
  if (!result.meshed()) {
    report.status = io::RunStatus::Failed;
    const auto j = report.toJson();
    raise(gMeshingError, app::failureMessage(args.file, report, result.stop), toPython(j["problems"]), toPython(j));
  }
  report.status = gradeRun(report.problems, true);
  auto data = std::make_shared<MeshData>();
  data->model = std::move(model);
  data->volume = result.volumeRan;
  if (data->volume) data->tets = std::move(result.volume.mesh);
  else data->surface = std::move(result.surface.mesh);
  data->dim = args.options.dim;
  data->order = args.options.order;
  data->status = statusName(report.status);
  data->report = report.toJson();
  if (report.status == io::RunStatus::Degraded)
    py::module_::import("logging").attr("getLogger")("anisomesh").attr("warning")(
        "%s", args.file + ": the mesh is degraded: " + app::degradedSummary(report) + " (Mesh.problems lists them all)");
  return makeMesh(std::move(data));
}

/// A token always: Ctrl-C stops the run through it (Worker.h).
void setTimeLimit(app::MeshArgs& args, std::optional<double> timeLimit) {
  if (timeLimit && !(*timeLimit >= 0)) refuse("time_limit must be a number of seconds ≥ 0");
  args.timeLimit = timeLimit.value_or(0);
  args.options.cancel = args.timeLimit > 0 ? std::make_shared<const CancelToken>(args.timeLimit)
                                           : std::make_shared<const CancelToken>();
}

py::object mesh(const py::object& path, std::optional<int> dim, std::optional<double> size, std::optional<double> hmax,
                std::optional<double> hmin, int order, bool quad, const std::string& quadMethod,
                const std::optional<std::string>& sizing, int threads, std::optional<double> maxElements,
                std::optional<double> timeLimit, const py::object& progress, std::optional<double> hmaxRel,
                std::optional<double> hminRel, std::optional<double> elementsPerCircle, std::optional<double> curvatureRatio,
                bool curvature, std::optional<double> gradation, std::optional<double> anisotropy,
                std::optional<double> contourAnisotropy, bool fragment, const std::string& overlaps,
                const std::string& internalFaces, std::optional<double> chordDeviationRel) {
  const auto t0 = std::chrono::steady_clock::now();
  const SizeKeywords sizes{size, hmax, hmin, hmaxRel, hminRel, elementsPerCircle, curvatureRatio,
                           gradation, anisotropy, contourAnisotropy, chordDeviationRel, curvature};
  app::MeshArgs args = meshArgs(pathOf(path), dim, order, quad, quadMethod, sizes, sizing, threads, maxElements, fragment, overlaps,
                                internalFaces);
  setTimeLimit(args, timeLimit);
  io::Report report;
  std::optional<app::MeshRun> run;
  runJob(args, report, t0, progress, [&] { run.emplace(app::meshFile(args, report)); });
  return meshObject(args, report, std::move(run->input.model), std::move(run->result), t0);
}

/// anisomesh.adapt(): the CLI's `adapt` (tools/app/AdaptRun.h) with its defaults (the
/// thesis' sizing table, γ_a 10).
py::object adapt(const py::object& path, const py::object& from, const std::string& field, std::optional<double> targetNodes,
                 std::optional<double> error, double norm, const std::string& hessian, std::optional<int> dim, int order,
                 std::optional<double> size, std::optional<double> hmax, std::optional<double> hmin,
                 std::optional<double> hmaxRel, std::optional<double> hminRel, std::optional<double> gradation,
                 std::optional<double> anisotropy, bool curvature, int threads, std::optional<double> timeLimit,
                 const py::object& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  app::AdaptArgs a;
  a.mesh.file = pathOf(path);
  a.from = pathOf(from);
  a.field = field;
  if (dim && *dim != 2 && *dim != 3) refuse("dim must be 2, 3 or None");
  if (order != 1 && order != 2) refuse("order must be 1 or 2");
  if (threads < 0 || threads > 4096) refuse("threads must be from 0 (all cores) to 4096");
  if (targetNodes && !(*targetNodes > 0)) refuse("target_nodes must be positive");
  if (error && !(*error > 0)) refuse("error must be positive");
  a.mesh.options.dim = dim.value_or(0);
  a.mesh.options.order = order;
  a.mesh.options.threads = threads;
  a.mesh.options.sizing.anisotropy = 10;
  const SizeKeywords sizes{size, hmax, hmin, hmaxRel, hminRel, {}, {}, gradation, anisotropy, {}, {}, curvature};
  sizes.apply(a.mesh.options.sizing);
  a.targetNodes = targetNodes.value_or(0);
  a.error = error.value_or(0);
  a.norm = norm;
  a.hessian = choice<HessianMethod>("hessian", hessian, {{"ls", HessianMethod::LeastSquares}, {"l2", HessianMethod::DoubleL2}});
  setTimeLimit(a.mesh, timeLimit);
  io::Report report;
  std::optional<app::AdaptRun> run;
  runJob(a.mesh, report, t0, progress, [&] {
    const app::FieldInput f = app::readField(a);
    run.emplace(app::adaptFile(a, f, report));
  });
  return meshObject(a.mesh, report, std::move(run->input.model), std::move(run->result.mesh), t0);
}

py::object info(const py::object& path, bool faces, bool fragment, const std::string& overlaps) {
  const app::InfoRequest r{pathOf(path), faces, fragment, overlapPolicy(overlaps)};
  nlohmann::ordered_json j;
  const CancelToken never;  // info reads and prepares: no cancellation point (Ctrl-C waits for it)
  runInWorker([&] { j = app::infoJson(r); }, never, py::none());
  return toPython(j);
}

}  // namespace

void bindCalls(py::module_& m) {
  gError = PyErr_NewException("anisomesh.Error", PyExc_Exception, nullptr);
  m.add_object("Error", gError);
  gInputError = PyErr_NewException("anisomesh.InputError", gError.ptr(), nullptr);
  m.add_object("InputError", gInputError);
  gMeshingError = PyErr_NewException("anisomesh.MeshingError", gError.ptr(), nullptr);
  m.add_object("MeshingError", gMeshingError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      setError(gInputError, e.what(), py::list(), py::none());
    } catch (const MeshingError& e) {
      setError(gMeshingError, e.what(), py::list(), py::none());
    }
  });

  m.def("mesh", &mesh, py::arg("path"), py::kw_only(), py::arg("dim") = py::none(), py::arg("size") = py::none(),
        py::arg("hmax") = py::none(), py::arg("hmin") = py::none(), py::arg("order") = 1, py::arg("quad") = false,
        py::arg("quad_method") = "merge", py::arg("sizing") = py::none(), py::arg("threads") = 0,
        py::arg("max_elements") = py::none(), py::arg("time_limit") = py::none(), py::arg("progress") = py::none(),
        py::arg("hmax_rel") = py::none(), py::arg("hmin_rel") = py::none(), py::arg("elements_per_circle") = py::none(),
        py::arg("curvature_ratio") = py::none(), py::arg("curvature") = true, py::arg("gradation") = py::none(),
        py::arg("anisotropy") = py::none(), py::arg("contour_anisotropy") = py::none(), py::arg("fragment") = true,
        py::arg("overlaps") = "merge", py::arg("internal_faces") = "auto", py::arg("chord_deviation_rel") = py::none(),
        "Meshes a CAD file (STEP, IGES, BREP, .json analytic) as `anisomesh mesh` does with the same options; "
        "returns an anisomesh.Mesh. progress(phase, done, total, detail) is called from this thread.");
  m.def("adapt", &adapt, py::arg("path"), py::kw_only(), py::arg("from_mesh"), py::arg("field"),
        py::arg("target_nodes") = py::none(), py::arg("error") = py::none(), py::arg("norm") = 2.0,
        py::arg("hessian") = "ls", py::arg("dim") = py::none(), py::arg("order") = 1, py::arg("size") = py::none(),
        py::arg("hmax") = py::none(), py::arg("hmin") = py::none(), py::arg("hmax_rel") = py::none(),
        py::arg("hmin_rel") = py::none(), py::arg("gradation") = py::none(), py::arg("anisotropy") = py::none(),
        py::arg("curvature") = true, py::arg("threads") = 0, py::arg("time_limit") = py::none(),
        py::arg("progress") = py::none(),
        "Meshes a CAD file adapted to a field of a solver's mesh, as `anisomesh adapt` does with the same options "
        "(from_mesh: .msh .vtu .frd .inp; field: NAME, NAME:x|y|z|N, NAME:mises|p1|p2|p3; target_nodes default: "
        "the node count of from_mesh); returns an anisomesh.Mesh whose report has the 'adapt' block.");
  m.def("info", &info, py::arg("path"), py::kw_only(), py::arg("faces") = false, py::arg("fragment") = true,
        py::arg("overlaps") = "merge", "What `anisomesh info --json [--faces]` prints, as a dict");
}

}  // namespace aniso::python
