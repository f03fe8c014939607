#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "io/AtomicFile.h"
#include "io/MeshWriter.h"
#include "io/Report.h"
#include "io/SizingFile.h"
#include "mesher/core/Error.h"
#include "mesher/core/Log.h"
#include "mesher/core/FileExtension.h"
#include "mesher/highorder/Order2.h"
#include "tools/cli/Commands.h"
#include "mesher/quad/QuadQuality.h"
#include "mesher/surface/SurfaceMesher.h"
#include "mesher/volume/CoarseSolids.h"
#include "mesher/volume/ThinBoundary.h"
#include "mesher/volume/VolumeMesher.h"
#include "tools/cli/BudgetReport.h"
#include "tools/cli/VolumeReport.h"
#include "tools/cli/ModelInput.h"
#include "tools/cli/SizingReport.h"

namespace aniso::cli {
namespace {

nlohmann::ordered_json optionsJson(const MeshArgs& a) {
  const SizingParameters& s = a.options.sizing;
  nlohmann::ordered_json j;
  j["output"] = a.output;
  j["dim"] = a.options.dim;
  j["order"] = a.options.order;
  j["quad"] = a.options.quad;
  if (a.options.quad) {
    const QuadMethod m = a.options.quadMethod;
    j["quad_method"] = m == QuadMethod::Merge ? "merge" : (m == QuadMethod::Morph ? "morph" : "mixed");
  }
  j["threads"] = a.options.threads;
  j["fragment"] = a.fragment;
  j["overlaps"] = cad::overlapPolicyName(a.overlaps);
  j["anisotropy"] = s.anisotropy;
  j["gradation"] = s.gradation;
  j["curvature_ratio"] = s.curvatureRatio;
  j["contour_anisotropy"] = s.contourAnisotropy;
  j["hmax_rel"] = s.hmaxRel;
  j["hmin_rel"] = s.hminRel;
  if (s.size) j["size"] = *s.size;
  j["curvature"] = s.curvature;
  if (s.hmax) j["hmax"] = *s.hmax;
  if (s.hmin) j["hmin"] = *s.hmin;
  if (!a.options.sizingFile.empty()) j["sizing"] = a.options.sizingFile;
  if (a.timeLimit > 0) j["time_limit"] = a.timeLimit;
  return j;
}

/// Options that are wrong whatever the model: exit 2 before any work.
void checkArguments(const MeshArgs& a) {
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
[[noreturn]] void failRun(const MeshArgs& a, io::Report& r, std::chrono::steady_clock::time_point t0) {
  r.status = io::RunStatus::Failed;
  r.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  writeReport(a, r);
  const Problem* p = firstShortcoming(r);
  throw MeshingError(a.file + ": " + (p ? entityLabel(p->entity) + ": " + p->detail : std::string("nothing could be meshed")));
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

/// The name of the first solid whose shells use each face ("" for a face of no solid).
std::vector<std::string> facePartNames(const Model& m) {
  std::vector<std::string> out(m.faces.size());
  for (std::size_t s = 0; s < m.solids.size(); ++s)
    for (const int f : m.solidFaces(static_cast<int>(s)))
      if (f >= 0 && static_cast<std::size_t>(f) < out.size() && out[static_cast<std::size_t>(f)].empty())
        out[static_cast<std::size_t>(f)] = m.solids[s].name;
  return out;
}

/// Model::check() as problems of the run, and the faces that cannot be meshed at all (an
/// unusable face, or a face of an unusable edge). Throws MeshingError when a solid or shell
/// is unusable: nothing sensible could be meshed.
std::vector<char> gradeModel(const MeshArgs& a, const Model& topo, io::Report& report,
                             std::chrono::steady_clock::time_point t0) {
  const std::vector<std::string> parts = facePartNames(topo);
  std::vector<char> skip(topo.faces.size(), 0);
  bool fatal = false;
  for (const ModelIssue& i : topo.check()) {
    // the message names its entity; the problem's detail is the rest of it
    const std::size_t colon = i.message.find(": ");
    const std::string detail = colon == std::string::npos ? i.message : i.message.substr(colon + 2);
    EntityRef ref{i.kind, i.index + 1, {}};
    if (i.kind == EntityKind::Face) ref.part = parts[static_cast<std::size_t>(i.index)];
    Problem p{ref, Severity::Note, "cad-defect", detail, "model"};
    if (i.level == ModelIssue::Level::Gap) {
      p.severity = Severity::Degraded;
      p.code = "loop-gap";
      p.detail += "; meshed across the gap";
    } else if (i.level == ModelIssue::Level::Unusable) {
      p.severity = Severity::Failed;
      p.code = "cad-unusable";
      if (i.kind == EntityKind::Face) skip[static_cast<std::size_t>(i.index)] = 1;
      else if (i.kind == EntityKind::Edge)
        for (const int f : topo.edges[static_cast<std::size_t>(i.index)].faces) skip[static_cast<std::size_t>(f)] = 1;
      else fatal = true;
    }
    report.problems.push_back(std::move(p));
  }
  if (fatal || std::all_of(skip.begin(), skip.end(), [](char c) { return c != 0; })) {
    const Problem* p = firstOf(report.problems, Severity::Failed);
    report.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    writeReport(a, report);
    throw MeshingError(a.file + ": invalid model topology: " + entityLabel(p->entity) + ": " + p->detail);
  }
  return skip;
}

}  // namespace

static void fillSurfaceReport(const Model& topo, const SurfaceMeshResult& sr, io::Report& report) {
  report.nodes = static_cast<long long>(sr.mesh.nodes.size());
  report.triangles = static_cast<long long>(sr.mesh.triangles.size());
  auto stats = [](const QualityStats& s) {
    return nlohmann::ordered_json{{"mean", s.count() ? s.mean() : 0.0}, {"sd", s.stddev()},
                                  {"min", s.count() ? s.min() : 0.0}, {"max", s.count() ? s.max() : 0.0}};
  };
  report.quality["eta_M"] = stats(sr.quality.eta);
  report.quality["mu_M"] = stats(sr.quality.mu);
  report.quality["E_K"] = stats(sr.quality.ek);
  nlohmann::ordered_json faces = nlohmann::ordered_json::array();
  for (size_t f = 0; f < sr.faces.size(); ++f) {
    const FaceOutcome& o = sr.faces[f];
    faces.push_back({{"face", f + 1}, {"triangles", o.triangles}, {"eta_M", o.quality.eta.count() ? o.quality.eta.mean() : 0.0},
                     {"mu_M", o.quality.mu.count() ? o.quality.mu.mean() : 0.0},
                     {"E_K", o.quality.ek.count() ? o.quality.ek.mean() : 0.0},
                     {"missing_boundary_edges", o.stats.missingBoundaryEdges}});
  }
  // the surface's problems, replaced when the surface is meshed again (proximity rounds)
  report.problems.erase(std::remove_if(report.problems.begin(), report.problems.end(),
                                       [](const Problem& p) { return p.where == "surface"; }),
                        report.problems.end());
  const std::vector<std::string> parts = facePartNames(topo);
  for (size_t f = 0; f < sr.faces.size(); ++f) {
    const std::vector<std::string>& ps = sr.faces[f].problems;
    if (ps.empty()) continue;
    std::string detail = "not meshed: " + ps.front();
    if (ps.size() > 1) detail += " (and " + std::to_string(ps.size() - 1) + " more)";
    report.problems.push_back({EntityRef::face(static_cast<int>(f), parts[f]), Severity::Failed, "face-mesh", detail, "surface"});
  }
  report.quality["faces"] = faces;
  report.quads = static_cast<long long>(sr.mesh.quads.size());
  if (!sr.mesh.quads.empty()) {  // --quad: fraction, 3D scaled Jacobian, μ_M over all edges
    const quad::SurfaceQuadQuality q = quad::surfaceQuadQuality(sr.mesh);
    report.quality["quad"] = {{"fraction", q.fraction},
                              {"scaled_jacobian", {{"min", q.jacobian.min()}, {"mean", q.jacobian.mean()}}},
                              {"boundary_scaled_jacobian",
                               {{"quads", q.boundaryJacobian.count()}, {"min", q.boundaryJacobian.count() ? q.boundaryJacobian.min() : 0.0},
                                {"mean", q.boundaryJacobian.mean()}}},
                              {"mu_M", {{"mean", sr.quality.mu.mean()}, {"sd", sr.quality.mu.stddev()}}}};
  }
  const SurfaceMesh::EdgeCounts ec = sr.mesh.edgeCounts();
  reportBudget(sr.budget, report);
  report.extra["surface"] = {{"open_edges", ec.open}, {"non_manifold_edges", ec.nonManifold},
                             {"misoriented_edges", ec.misoriented}};
}

/// Faces the surface mesher could not mesh (a finer surface must not lose more of them).
static std::size_t failedFaces(const SurfaceMeshResult& sr) {
  return static_cast<std::size_t>(
      std::count_if(sr.faces.begin(), sr.faces.end(), [](const FaceOutcome& o) { return !o.problems.empty(); }));
}

/// --order 2: quadratic elements (mesher/highorder/Order2.h), after meshing and before
/// writing; the report gives the mid-edge nodes made and the elements left straight.
template <class Mesh>
static void elevateForOutput(const Model& topo, Mesh& mesh, io::Report& report) {
  const auto t = std::chrono::steady_clock::now();
  const Order2Stats s = elevateToOrder2(topo, mesh);
  report.times.emplace_back("order2", std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count());
  report.nodes += s.midNodes;
  report.extra["order2"] = {{"mid_nodes", s.midNodes}, {"straightened", s.straightened}};
}

/// Rounds of alg. 3.3's outer loop: the surface meshed again, finer where the solid is
/// thinner than its triangles (ThinBoundary.h), then the volume again.
constexpr int kMaxProximityRounds = 2;
/// Budget of a round: the sources may ask for at most this many times the surface mesh's
/// triangles (predictedTriangles); beyond it their sizes are scaled up until the prediction
/// fits (sourcesWithinBudget: refined as far as the budget allows). A resource guard, not a
/// quality rule; measured: periodic_u_cst asks for 8.6x (becomes 7.5x, mean ratio 0.70 ->
/// 0.86), simple_plane's skins for 30x (without the guard 30k triangles became 990k in
/// two rounds, 9.6 M tets, 300 s).
constexpr double kMaxProximityGrowth = 10.0;
/// A part thin as a whole — at least this share of the surface's triangles thin — is refined
/// as far as the budget allows when its sources ask for more (sourcesWithinBudget): nearly
/// every tet spans it, so the mean quality follows the ratio of triangle size to thickness
/// (periodic_u_cst at the defaults: 77 % thin, asks 14.7x; scaled by 1.22 to 10x, mean
/// ratio 0.68 -> 0.84). A part thin in places (an assembly's skins: simple_plane, 33 %,
/// asks 22x) keeps its surface: few tets span it, and scaled to the budget it grew to 5.4 M
/// tets in 220 s at the defaults (mean ratio 0.81 -> 0.85).
constexpr double kThinWholeShare = 0.5;
/// A round whose sources would add less than this share of triangles is not run.
constexpr double kMinProximityGrowth = 1.05;

/// Dim 3: the volume mesh of every solid (VolumeMesher.h), reported and written; no file
/// when a solid fails (exit 3). Alg. 3.3: while a solid is thinner than its boundary
/// triangles (at most kMaxProximityRounds times), those faces get sizing sources and the
/// whole surface is meshed again (shared edges stay consistent), then the volume; the
/// report's "proximity" block gives the rounds and the faces refined. When the volume of
/// the finer surface fails, the first surface is meshed instead (without the loop).
static int runVolume(const MeshArgs& args, const Model& topo, SurfaceMesherInput sin, SurfaceMeshResult sr,
                     const UserSizing& user, io::Report& report, const io::WriteOptions& wopt,
                     std::chrono::steady_clock::time_point t0) {
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  UserSizing sizing = user;  // the user's and the proximity sources, for the surface
  VolumeMesherInput vin;
  vin.model = &topo;
  vin.options = args.options;
  vin.user = &user;  // the volume follows the finer surface (eq. 3.3) without box sources
  const SurfaceMeshResult first = sr;
  int rounds = 0;
  std::size_t facesRefined = 0;
  double proximitySeconds = 0;
  bool loop = true;
  double predicted = 0, budgetFactor = 1;
  VolumeMeshResult vr;
  for (;;) {
    vin.surface = &sr.mesh;
    vin.stopWhenThin = loop && rounds < kMaxProximityRounds;
    const auto tr = Clock::now();
    vr = meshVolumes(vin);
    if (!vin.stopWhenThin && rounds > 0 && !vr.ok()) {
      // the finer surface could not be meshed: the volume of the first surface instead
      sr = first;
      fillSurfaceReport(topo, sr, report);
      rounds = 0;
      facesRefined = 0;
      loop = false;
      proximitySeconds += seconds(tr, Clock::now());
      continue;
    }
    if (vr.thin.empty() || !vin.stopWhenThin) break;
    const double triangles = static_cast<double>(sr.mesh.triangles.size());
    const double budget = kMaxProximityGrowth * triangles;
    std::vector<SizingSource> sources = thinSources(vr.thin, args.options.sizing.hminFor(topo.diagonal()));
    predicted = predictedTriangles(sr.mesh, sources);
    if (predicted > budget && static_cast<double>(vr.thin.size()) >= kThinWholeShare * triangles) {
      sources = sourcesWithinBudget(sr.mesh, sources, budget, &budgetFactor);
      predicted = predictedTriangles(sr.mesh, sources);
    }
    if (sources.empty() || predicted > budget || predicted < kMinProximityGrowth * triangles) {
      loop = false;  // nothing (left) to refine, or beyond the budget: the volume of this surface
      continue;
    }
    sizing.sources.insert(sizing.sources.end(), sources.begin(), sources.end());
    sin.user = &sizing;
    SurfaceMeshResult finer = meshSurfaces(sin);
    proximitySeconds += seconds(tr, Clock::now());
    ++rounds;
    if (failedFaces(finer) > failedFaces(sr)) {  // keep the surface that meshed: the volume as it is
      loop = false;
      continue;
    }
    facesRefined += sources.size();
    sr = std::move(finer);
    fillSurfaceReport(topo, sr, report);
  }
  // a solid still below the quality bar: its surface once more at a finer size, kept when
  // the whole mesh's mean ratio is better (CoarseSolids.h)
  int coarseSolids = 0;
  bool coarseKept = false;
  if (vr.ok()) {
    const std::vector<SizingSource> coarse = coarseSolidSources(topo, sr.mesh, vr.solids);
    coarseSolids = static_cast<int>(coarse.size());
    if (!coarse.empty()) {
      const auto tr = Clock::now();
      UserSizing finerSizing = sizing;
      finerSizing.sources.insert(finerSizing.sources.end(), coarse.begin(), coarse.end());
      sin.user = &finerSizing;
      // a retry that fails (by status or by an error) leaves the first result
      try {
        SurfaceMeshResult finer = meshSurfaces(sin);
        if (failedFaces(finer) <= failedFaces(sr)) {
          VolumeMesherInput fin = vin;
          fin.surface = &finer.mesh;
          fin.stopWhenThin = false;
          VolumeMeshResult fvr = meshVolumes(fin);
          if (fvr.ok() && fvr.quality.meanRatio.mean() > vr.quality.meanRatio.mean()) {
            vr = std::move(fvr);
            sr = std::move(finer);
            fillSurfaceReport(topo, sr, report);
            coarseKept = true;
          }
        }
      } catch (const Cancelled&) {
        throw;
      } catch (const MeshingError& e) {
        logWarning(std::string("coarse solids: the finer surface failed (") + e.what() + "); the first mesh is kept");
      }
      proximitySeconds += seconds(tr, Clock::now());
    }
  }
  report.extra["coarse_solids"] = {{"solids", coarseSolids}, {"refined_kept", coarseKept}};
  report.extra["proximity"] = {{"rounds", rounds},
                               {"faces_refined", facesRefined},
                               {"thin_triangles_left", vr.thin.size()},
                               {"predicted_triangles", predicted},
                               {"budget_factor", budgetFactor},
                               {"seconds", proximitySeconds}};
  for (const auto& p : vr.times) report.times.push_back(p);
  fillVolumeReport(topo, vr, report);
  report.extra["sizing"] = sizingReport(args.options.sizing, topo.diagonal(), sr.mesh, &vr.mesh);
  // a solid that failed leaves the mesh degraded; no solid meshed at all fails the run
  if (vr.mesh.tets.empty()) failRun(args, report, t0);
  if (args.options.order == 2) elevateForOutput(topo, vr.mesh, report);
  const auto tw = Clock::now();
  io::writeVolumeMesh(topo, vr.mesh, args.output, wopt);
  report.times.emplace_back("write", seconds(tw, Clock::now()));
  finishRun(args, report, t0);
  return 0;
}

bool isKnownOutputExtension(const std::string& path) {
  static const char* known[] = {".msh", ".inp", ".vtu", ".stl", ".obj", ".off", ".unv"};
  const std::string ext = lowerExtension(path);
  return std::any_of(std::begin(known), std::end(known), [&](const char* k) { return ext == k; });
}

static int meshRun(const MeshArgs& given, io::Report& report) {
  MeshArgs args = given;
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  auto seconds = [](Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };
  checkArguments(args);
  // The sizing file is read (and checked) before the model, so a bad one fails fast.
  const UserSizing user = args.options.sizingFile.empty() ? UserSizing{} : io::readSizingFile(args.options.sizingFile);

  report.input = args.file;
  report.options = optionsJson(args);

  // Reading and preparing the model: failures here are bad input (exit 2).
  ModelInput in = loadModel(args.file, args.fragment, args.overlaps, args.options.cancel.get());
  checkCancel(args.options.cancel.get(), "reading");
  report.times = in.times;
  report.extra["model"] = in.summary;
  int dim = args.options.dim;
  if (dim == 0) dim = in.solids > 0 ? 3 : 2;
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
  const Model& topo = in.model;
  // CAD defects: faces that cannot be used are left out (the run is then degraded); a model
  // with nothing usable is refused
  std::vector<char> skip = gradeModel(args, topo, report, t0);

  const std::unique_ptr<ControlSpace2d> analytic = analyticControlSpace(in);
  SurfaceMesherInput sin;
  sin.model = &topo;
  sin.options = args.options;
  sin.analytic = analytic.get();
  sin.user = &user;
  sin.skipFaces = std::move(skip);
  SurfaceMeshResult sr = meshSurfaces(sin);
  for (const auto& p : sr.times) report.times.push_back(p);
  fillSurfaceReport(topo, sr, report);
  // faces that failed are left out (degraded); nothing meshed fails the run
  if (sr.mesh.triangles.empty() && sr.mesh.quads.empty()) failRun(args, report, t0);
  io::WriteOptions wopt;
  wopt.binary = args.binary;
  wopt.mshVersion = args.mshVersion;
  if (dim == 3) return runVolume(args, topo, sin, std::move(sr), user, report, wopt, t0);
  report.extra["sizing"] = sizingReport(args.options.sizing, topo.diagonal(), sr.mesh, nullptr);
  if (args.options.order == 2) elevateForOutput(topo, sr.mesh, report);
  const auto tw = Clock::now();
  io::writeSurfaceMesh(topo, sr.mesh, args.output, wopt);
  report.times.emplace_back("write", seconds(tw, Clock::now()));
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
    return meshRun(args, report);
  } catch (const Cancelled& e) {
    report.problems.push_back({EntityRef::model(), Severity::Failed, "time-limit", e.what(), "run"});
    report.status = io::RunStatus::Failed;
    report.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    writeReport(args, report);
    throw MeshingError(args.file + ": " + e.what());
  }
}

}  // namespace aniso::cli
