// anisomesh adapt MODEL --from MESH --field NAME -o OUT (issue 19): the field of a solver's
// mesh becomes a metric (least-squares Hessian recovery, Loseille–Alauzet Lp metric scaled
// to a node count or an error; mesher/adapt/), the metric at the old mesh's nodes becomes
// discrete point sources (thesis 3.3.1; mesher/sizing/PointSizing.h) intersected with the
// geometric sizing, and MODEL is meshed as by `anisomesh mesh` — the new boundary nodes lie
// on the CAD surfaces. The report gets an "adapt" block. --transfer writes the field's
// array (all components) at the new nodes into the output (.msh / .vtu; FieldTransfer.h).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "io/AtomicFile.h"
#include "io/readers/ReadMesh.h"
#include "io/readers/fields/NodalField.h"
#include "mesher/adapt/FieldTransfer.h"
#include "mesher/adapt/HessianRecovery.h"
#include "mesher/adapt/LpMetric.h"
#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"
#include "mesher/core/Log.h"
#include "mesher/volume/VolumeControlSpace.h"
#include "tools/cli/AdaptCommand.h"
#include "tools/cli/RunSummary.h"

namespace aniso::cli {
namespace {

/// The old mesh's box may miss the model's by this fraction of the model's diagonal per
/// side (a mesh of a curved model is inside it by its sagitta; a solver may shift nothing).
constexpr double kCoverTolerance = 0.05;

/// --target-nodes is met within this fraction when it can be: a mesh that misses it by more
/// is made again (at most kMaxCountRounds meshes in all) with the metric's target moved by a
/// secant step on log(count made) against log(count the metric is scaled to): the first step
/// assumes proportionality, later ones the measured slope (at most kCountSlope[1]). The
/// Lp metric's prediction (LpMetric.h) is calibrated on uniform metrics; anisotropic fields
/// that vary fast make up to ~50 % more nodes (the 10 mm cube, tanh front, second round),
/// a field the first mesh does not resolve fewer (the same cube from a size-1 mesh: 1932
/// for 3000, then 2248 for a metric scaled to 4658: slope 0.34).
/// The rounds stop early when the count cannot follow the metric: a measured slope below
/// kCountSlope[0] (the model bounds the count: thin walls keep sizes under a thickness,
/// hmin / hmax, curvature; the next step would rescale the metric by (asked / made)^5 or
/// more, to no effect: the holeplate from its h 5 mesh, 8000 asked, 19669 then 17667 nodes
/// at a metric scaled 0.41 times, slope 0.12; a third mesh at hmax made 18732), or a metric
/// already clamped to [hmin, hmax] (LpMetric::limited) on the side the count missed.
/// The mesh kept is the one closest to the count asked (made again when it is not the last).
constexpr double kCountTolerance = 0.15;
/// --target-nodes counts the output's nodes, the mid-side nodes of --order 2 too (what the
/// solver counts); the metric is first scaled to N / this many vertices: a Delaunay tet mesh
/// has ~5.5 tets and ~6.5 edges per vertex (7.5 nodes; less at the boundary: 7), a
/// triangle mesh 3 edges per vertex (4). The count rounds correct the rest.
constexpr double kQuadraticNodesPerVertex[4] = {1, 1, 4.0, 7.0};
constexpr int kMaxCountRounds = 3;
constexpr double kCountSlope[2] = {0.2, 1.5};

/// What the field gives every round: its recovered Hessians and the old mesh's measures
/// (the count rounds rescale the metric only).
struct FieldMetricInput {
  std::vector<Mat3> hessians;
  std::vector<double> measures;
  std::vector<Vec3> normals;
  std::vector<BoundaryFacet> boundary;
};

/// The cells of the top dimension of `m` (tetrahedra, else triangles) as a PatchMesh.
PatchMesh patchMesh(const io::ReadMesh& m, const std::string& path) {
  PatchMesh p;
  bool tets = false;
  for (io::CellType t : m.types) tets = tets || t == io::CellType::Tet || t == io::CellType::Tet10;
  p.dim = tets ? 3 : 2;
  p.nodes = m.nodes;
  for (std::size_t c = 0; c < m.cellCount(); ++c) {
    const io::CellType t = m.types[c];
    const bool take = tets ? (t == io::CellType::Tet || t == io::CellType::Tet10)
                           : (t == io::CellType::Triangle || t == io::CellType::Triangle6);
    if (!take) continue;
    p.conn.insert(p.conn.end(), m.cell(c), m.cell(c) + m.cellSize(c));
    p.offsets.push_back(static_cast<int>(p.conn.size()));
  }
  if (p.cellCount() == 0) throw InputError(path + ": no tetrahedra or triangles to read the field on");
  return p;
}

void checkCover(const PatchMesh& p, const Model& model, const std::string& path, const std::string& modelPath) {
  Box3 box;
  for (std::size_t c = 0; c < p.cellCount(); ++c)
    for (int a = p.offsets[c]; a < p.offsets[c + 1]; ++a) box.add(p.nodes[p.conn[a]]);
  const double tol = kCoverTolerance * model.diagonal();
  const bool covers = ((box.lo - model.bbox.lo).cwiseAbs().array() <= tol).all() &&
                      ((box.hi - model.bbox.hi).cwiseAbs().array() <= tol).all();
  if (!covers)
    throw InputError(path + ": its nodes do not cover the model " + modelPath +
                     " (their bounding box differs from the model's by more than " +
                     std::to_string(kCoverTolerance) + " of its diagonal): a mesh of another model?");
}

nlohmann::json adaptSizing(const AdaptArgs& a, const io::ReadMesh& old, const PatchMesh& p, const io::NodalField& field,
                           const FieldMetricInput& in, const Model& model, UserSizing& user) {
  checkCover(p, model, a.from, a.mesh.file);
  const SizingParameters& s = a.mesh.options.sizing;
  LpMetricParameters lp;
  lp.dim = p.dim;
  lp.norm = a.norm;
  lp.error = a.error;
  lp.targetNodes = a.error > 0 ? 0 : a.metricTarget;
  lp.hmin = s.hminFor(model.diagonal());
  lp.hmax = s.hmaxFor(model.diagonal());
  lp.anisotropy = s.anisotropy;
  LpMetric metric;
  try {
    metric = lpMetric(in.hessians, in.measures, in.normals, in.boundary, lp);
  } catch (const MeshingError& e) {
    throw InputError(a.from + ": field " + a.field + ": " + e.what());
  }
  if (metric.limited) logWarning("adapt: the asked node count or error is out of reach within [hmin, hmax]");
  // a volume's sizes are those of its surface triangles, its tets f times longer inside
  // (VolumeControlSpace.h): for tets of the metric's size, f times finer
  const double f = a.mesh.options.dim == 3 ? kVolumeLengthFactor : 1.0;
  std::vector<char> used(p.nodes.size(), 0);
  for (int v : p.conn) used[v] = 1;
  for (std::size_t i = 0; i < p.nodes.size(); ++i)
    if (used[i]) user.points.push_back({p.nodes[i], Metric3d::fromTensor(metric.metrics[i].tensor() * (f * f))});
  logInfo("adapt: " + std::to_string(user.points.size()) + " point sources, predicted " +
          std::to_string(static_cast<long long>(std::lround(metric.predictedNodes))) + " nodes");
  const auto [lo, hi] = std::minmax_element(field.values.begin(), field.values.end());
  return {{"from", a.from},
          {"field", a.field},
          {"field_min", *lo},
          {"field_max", *hi},
          {"old_nodes", old.nodes.size()},
          {"dim", p.dim},
          {"hessian", a.hessian == "l2" ? "double-l2" : "least-squares"},
          {"norm", a.norm},
          {"target_nodes", a.error > 0 ? 0.0 : a.targetNodes},
          {"metric_target_nodes", lp.targetNodes},
          {"first_nodes", a.firstNodes},
          {"target_error", lp.error},
          {"predicted_nodes", metric.predictedNodes},
          {"predicted_error", metric.predictedError},
          {"limited", metric.limited},
          {"hmin", lp.hmin},
          {"hmax", lp.hmax},
          {"anisotropy", lp.anisotropy}};
}

/// --transfer: the field's whole array at the new nodes, the report's adapt block told how
/// many lay outside the old mesh and how far.
NodeDataHook transferHook(const PatchMesh& p, const io::NodalField& field) {
  return [&p, &field](const std::vector<Vec3>& nodes, nlohmann::ordered_json& extra) {
    const TransferredField t = transferField(p, field.arrayValues, field.components, nodes);
    extra["adapt"]["transfer"] = {{"array", field.arrayName},
                                  {"components", field.components},
                                  {"nodes_outside", t.outside},
                                  {"max_distance_outside", t.maxDistance}};
    return std::vector<io::NodeData>{{field.arrayName, field.components, t.values}};
  };
}

}  // namespace

CLI::App* addAdaptCommand(CLI::App& app, AdaptArgs& a) {
  a.mesh.options.sizing.anisotropy = 10;
  CLI::App* cmd = app.add_subcommand("adapt", "Mesh a CAD model adapted to a field of a solver's mesh (Lp metric)");
  cmd->add_option("MODEL", a.mesh.file, "STEP, IGES, BREP or .json analytic model")->required();
  cmd->add_option("--from", a.from, "The solver's mesh with the field: .msh .vtu .frd .inp")->required();
  cmd->add_option("--field", a.field, "NAME, NAME:x|y|z|N, tensors NAME:mises|p1|p2|p3")->required();
  cmd->add_option("-o,--output", a.mesh.output, "Output mesh: .msh .inp .vtu .stl .obj .off .unv")->required();
  cmd->add_option("--target-nodes", a.targetNodes, "Node count asked (default: that of --from)")->check(CLI::PositiveNumber);
  cmd->add_option("--error", a.error, "Lp interpolation error asked, instead of a node count")->check(CLI::PositiveNumber);
  cmd->add_option("--norm", a.norm, "p of the Lp norm the metric minimises")->check(CLI::Range(1.0, 1e6))->capture_default_str();
  cmd->add_option("--hessian", a.hessian, "Hessian recovery: ls (least squares) or l2 (double L2 projection)")
      ->check(CLI::IsMember({"ls", "l2"}))->capture_default_str();
  cmd->add_option("--dim", a.mesh.options.dim, "2 or 3 (default: that of the field's mesh)")->check(CLI::IsMember({2, 3}));
  cmd->add_option("--order", a.mesh.options.order, "Element order")->check(CLI::IsMember({1, 2}))->capture_default_str();
  cmd->add_flag("--binary", a.mesh.binary, "Binary output where the format has it");
  cmd->add_flag("--transfer", a.transfer, "Write the field (all its components) at the new nodes (.msh .vtu)");
  cmd->add_option("--report", a.mesh.report, "Write the JSON run report here");
  cmd->fallthrough();
  return cmd;
}

namespace {

/// One mesh of the count rounds, read back from its report.
struct CountRound {
  double scaled = 0;  ///< the vertex count the metric was scaled to
  double made = 0;    ///< the output's nodes
  bool limitedAway = false;  ///< the metric was clamped on the side the count missed
};

CountRound readRound(const std::string& report, double scaled, double asked) {
  std::ifstream in(report);
  const nlohmann::json r = nlohmann::json::parse(in, nullptr, false);
  CountRound c{scaled, r.value("/counts/nodes"_json_pointer, 0.0), false};
  const double predicted = r.value("/adapt/predicted_nodes"_json_pointer, 0.0);
  // limited: the metric could not reach `scaled`; the prediction is on the side of the
  // count made when the metric is as coarse (or as fine) as it can be
  c.limitedAway = r.value("/adapt/limited"_json_pointer, false) && (c.made - asked) * (predicted - scaled) > 0;
  return c;
}

/// The report asked by --report gets the count rounds' outcome in its adapt block.
void recordCount(const std::string& report, double asked, double made, int meshes, const std::string& stop) {
  std::ifstream in(report);
  nlohmann::ordered_json r = nlohmann::ordered_json::parse(in, nullptr, false);
  if (r.is_discarded() || !r.contains("adapt")) return;
  r["adapt"]["count"] = {{"asked", asked},
                         {"made", made},
                         {"meshes", meshes},
                         {"reached", std::abs(made / asked - 1) <= kCountTolerance},
                         {"stop", stop}};
  io::writeFileAtomically(report, r.dump(1) + "\n");
}

std::string count(double n) { return std::to_string(static_cast<long long>(std::llround(n))); }

std::string ratio(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

}  // namespace

int runAdapt(const AdaptArgs& given) {
  AdaptArgs a = given;
  if (a.targetNodes > 0 && a.error > 0) throw InputError("adapt: give --target-nodes or --error, not both");
  if (!(a.norm >= 1)) throw InputError("adapt: --norm must be at least 1");
  if (!(a.mesh.options.sizing.anisotropy >= 1)) throw InputError("adapt: --anisotropy must be at least 1");
  const std::string ext = lowerExtension(a.mesh.output);
  if (a.transfer && ext != ".msh" && ext != ".vtu")
    throw InputError(a.mesh.output + ": --transfer writes the field into .msh or .vtu only");
  // the field first: a bad one fails before the model is read
  const io::ReadMesh old = io::readMesh(a.from);
  const io::NodalField field = io::selectField(old, a.field, a.from);
  const PatchMesh p = patchMesh(old, a.from);
  const FieldMetricInput in{
      recoverHessian(p, field.values, a.hessian == "l2" ? HessianMethod::DoubleL2 : HessianMethod::LeastSquares),
      nodeMeasures(p), nodeNormals(p), boundaryFacets(p)};
  MeshArgs& m = a.mesh;
  if (m.options.dim == 0) m.options.dim = p.dim;
  m.anisotropyGiven = true;  // the adapted metric's γ_a holds in the volume too
  m.extraSizing = [&a, &old, &p, &field, &in](const Model& model, UserSizing& user) {
    return adaptSizing(a, old, p, field, in, model, user);
  };
  const NodeDataHook nodeData = a.transfer ? transferHook(p, field) : NodeDataHook();
  if (a.error > 0) return runMesh(m, nodeData);
  if (!(a.targetNodes > 0)) a.targetNodes = static_cast<double>(old.nodes.size());
  // the count made is read from the report: a temporary one when none is asked
  const bool ownReport = m.report.empty();
  if (ownReport)
    m.report = (std::filesystem::temp_directory_path() / ("anisomesh-adapt-" + std::to_string(::getpid()) + ".json")).string();
  struct Remove {
    std::string path;
    ~Remove() { if (!path.empty()) std::filesystem::remove(path); }
  } cleanup{ownReport ? m.report : std::string()};
  const double asked = a.targetNodes;
  auto miss = [asked](const CountRound& r) { return std::abs(std::log(r.made / asked)); };
  std::vector<CountRound> rounds;
  a.metricTarget = a.mesh.options.order == 2 ? asked / kQuadraticNodesPerVertex[p.dim] : asked;
  std::string stop;
  io::Report last;  // the summary printed is the last mesh's (the one written)
  for (;;) {
    const int rc = runMesh(m, nodeData, &last);
    if (rc != 0) return rc;
    rounds.push_back(readRound(m.report, a.metricTarget, asked));
    const CountRound& r = rounds.back();
    if (!(r.made > 0)) return rc;
    if (std::abs(r.made / asked - 1) <= kCountTolerance) {
      stop = "within tolerance";
      break;
    }
    double slope = 1;
    if (rounds.size() > 1) {
      const CountRound& q = rounds[rounds.size() - 2];
      slope = std::log(r.made / q.made) / std::log(r.scaled / q.scaled);
      if (!(slope >= kCountSlope[0])) {
        stop = "count bound by the model";
        logWarning("adapt: " + count(r.made) + " nodes for " + count(asked) + " asked: the count hardly follows the metric (" +
                   count(q.made) + " then " + count(r.made) + " nodes for a metric scaled " +
                   ratio(r.scaled / q.scaled) + " times): the model bounds it (thin walls, hmin / hmax, curvature)");
        break;
      }
    }
    if (r.limitedAway) {
      stop = "metric at hmin / hmax";
      logWarning("adapt: " + count(r.made) + " nodes for " + count(asked) +
                 " asked: the metric is already at its bound (hmin / hmax) on that side");
      break;
    }
    if (static_cast<int>(rounds.size()) == kMaxCountRounds) {
      stop = "rounds";
      logWarning("adapt: " + count(r.made) + " nodes for " + count(asked) + " asked after " +
                 std::to_string(kMaxCountRounds) + " meshes (tolerance " + count(100 * kCountTolerance) + " %)");
      break;
    }
    logInfo("adapt: " + count(r.made) + " nodes for " + count(asked) + " asked: meshing again with the metric rescaled");
    if (a.firstNodes == 0) a.firstNodes = r.made;
    a.metricTarget *= std::pow(asked / r.made, 1 / std::min(slope, kCountSlope[1]));
  }
  const auto best = std::min_element(rounds.begin(), rounds.end(),
                                     [&miss](const CountRound& x, const CountRound& y) { return miss(x) < miss(y); });
  int meshes = static_cast<int>(rounds.size());
  double made = rounds.back().made;
  if (best != rounds.end() - 1) {
    logInfo("adapt: meshing again the closest of the " + std::to_string(meshes) + " meshes (" + count(best->made) + " nodes)");
    a.metricTarget = best->scaled;
    const int rc = runMesh(m, nodeData, &last);
    if (rc != 0) return rc;
    ++meshes;
    made = readRound(m.report, a.metricTarget, asked).made;
  }
  if (!ownReport) recordCount(m.report, asked, made, meshes, stop);
  printRunSummary(last, m.output);
  return 0;
}

}  // namespace aniso::cli
