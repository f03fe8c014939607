#include "tools/app/RunReport.h"

#include "io/ElementQuality.h"
#include "mesher/quad/QuadQuality.h"
#include "tools/app/BudgetReport.h"
#include "tools/app/VolumeReport.h"

namespace aniso::app {
namespace {

nlohmann::ordered_json stats(const QualityStats& s) {
  return nlohmann::ordered_json{{"mean", s.count() ? s.mean() : 0.0}, {"sd", s.stddev()},
                                {"min", s.count() ? s.min() : 0.0}, {"max", s.count() ? s.max() : 0.0}};
}

double meanOf(const QualityStats& s) { return s.count() ? s.mean() : 0.0; }

void fillSurfaceReport(const SurfaceMeshResult& sr, io::Report& report) {
  report.nodes = static_cast<long long>(sr.mesh.nodes.size());
  report.triangles = static_cast<long long>(sr.mesh.triangles.size());
  report.quality["eta_M"] = stats(sr.quality.eta);
  report.quality["mu_M"] = stats(sr.quality.mu);
  report.quality["E_K"] = stats(sr.quality.ek);
  nlohmann::ordered_json faces = nlohmann::ordered_json::array();
  for (size_t f = 0; f < sr.faces.size(); ++f) {
    const FaceOutcome& o = sr.faces[f];
    faces.push_back({{"face", f + 1}, {"triangles", o.triangles}, {"eta_M", meanOf(o.quality.eta)},
                     {"mu_M", meanOf(o.quality.mu)}, {"E_K", meanOf(o.quality.ek)},
                     {"missing_boundary_edges", o.stats.missingBoundaryEdges},
                     {"refinement_limit_reached", o.stats.insertionLimitReached},
                     {"folds_left", o.stats.foldsLeft},  // the face mesher's; the final check grades the mesh
                     {"flat_triangles_left", o.stats.flatTrianglesLeft}});
  }
  report.quality["faces"] = faces;
  report.quads = static_cast<long long>(sr.mesh.quads.size());
  report.quality["elements"] = io::elementQuality(sr.mesh);
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

}  // namespace

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
  j["internal_faces"] = a.options.internalFaces == InternalFaces::Crack
                            ? "crack"
                            : (a.options.internalFaces == InternalFaces::Bond ? "bond" : "auto");
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

void fillRunReport(const Model& model, const MeshResult& r, io::Report& report) {
  report.problems.insert(report.problems.end(), r.problems.begin(), r.problems.end());
  for (const auto& p : r.times) report.times.push_back(p);
  if (r.stop != PipelineStop::Model) {
    fillSurfaceReport(r.surface, report);
    const SurfaceRepairStats& sr = r.surfaceRepair;
    const SurfaceGeometryCheck& c = r.surfaceCheck;
    report.extra["surface_repair"] = {{"nodes_merged", sr.nodesMerged},     {"caps_flipped", sr.capsFlipped},
                                      {"folds_repaired", sr.foldsRepaired}, {"folded_edges", c.foldedEdges},
                                      {"flat_triangles", c.flatTriangles},  {"open_edges_closed_shells", c.openEdges},
                                      {"crossing_pairs", c.crossingPairs}};
  }
  if (r.volumeRan) {
    report.extra["coarse_solids"] = {{"solids", r.coarse.solids}, {"refined_kept", r.coarse.refinedKept}};
    const ProximityOutcome& px = r.proximity;
    report.extra["proximity"] = {{"rounds", px.rounds},
                                 {"faces_refined", px.facesRefined},
                                 {"thin_triangles_left", px.thinTrianglesLeft},
                                 {"predicted_triangles", px.predictedTriangles},
                                 {"budget_factor", px.budgetFactor},
                                 {"seconds", px.seconds}};
    nlohmann::ordered_json refined = nlohmann::ordered_json::array();
    for (const auto& [f, h] : px.refined) refined.push_back({{"face", f + 1}, {"size", h}});
    report.extra["proximity"]["refined"] = std::move(refined);
    fillVolumeReport(model, r.volume, report);
    // the repair stage before the volume and after its split rounds, as one count
    nlohmann::ordered_json& rec = report.extra["recovery"];
    rec["surface_folds_repaired"] = r.volume.foldsRepaired + r.surfaceRepair.foldsRepaired;
    rec["surface_nodes_merged"] = r.volume.surfaceNodesMerged + r.surfaceRepair.nodesMerged;
    rec["surface_caps_flipped"] = r.volume.surfaceCapsFlipped + r.surfaceRepair.capsFlipped;
  }
  if (r.order2)  // the counts above are of the elevated mesh: its nodes include the mid nodes
    report.extra["order2"] = {{"mid_nodes", r.order2->midNodes}, {"straightened", r.order2->straightened}};
  nlohmann::ordered_json stages = nlohmann::ordered_json::array();
  for (const StageDecision& d : r.decisions)
    stages.push_back({{"stage", d.stage}, {"decision", d.decision}, {"reason", d.reason}});
  report.extra["stages"] = stages;
}

}  // namespace aniso::app
