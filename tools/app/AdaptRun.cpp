#include "tools/app/AdaptRun.h"

#include <algorithm>

#include "mesher/core/Error.h"
#include "mesher/pipeline/Pipeline.h"
#include "tools/app/MeshRun.h"

namespace aniso::app {
namespace {

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

nlohmann::ordered_json adaptJson(const AdaptArgs& a, const FieldInput& f, const AdaptResult& r) {
  const auto [lo, hi] = std::minmax_element(f.field.values.begin(), f.field.values.end());
  const AdaptSourcesRecord& m = r.metric;
  nlohmann::ordered_json j = {{"from", a.from},
                              {"field", a.field},
                              {"field_min", *lo},
                              {"field_max", *hi},
                              {"old_nodes", f.mesh.nodes.size()},
                              {"dim", f.patch.dim},
                              {"hessian", a.hessian == HessianMethod::DoubleL2 ? "double-l2" : "least-squares"},
                              {"norm", a.norm},
                              {"target_nodes", a.error > 0 ? 0.0 : a.targetNodes},
                              {"metric_target_nodes", m.targetVertices},
                              {"first_nodes", r.firstNodes},
                              {"target_error", a.error},
                              {"predicted_nodes", m.predictedNodes},
                              {"predicted_error", m.predictedError},
                              {"limited", m.limited},
                              {"hmin", m.hmin},
                              {"hmax", m.hmax},
                              {"anisotropy", m.anisotropy}};
  if (a.error > 0) return j;
  const double made = r.rounds[r.kept].made;
  j["count"] = {{"asked", a.targetNodes},
                {"made", made},
                {"meshes", r.rounds.size()},
                {"reached", r.reached()},
                {"stop", r.stop}};
  return j;
}

}  // namespace

FieldInput readField(const AdaptArgs& a) {
  if (a.targetNodes > 0 && a.error > 0) throw InputError("adapt: give --target-nodes or --error, not both");
  if (!(a.norm >= 1)) throw InputError("adapt: --norm must be at least 1");
  if (!(a.mesh.options.sizing.anisotropy >= 1)) throw InputError("adapt: --anisotropy must be at least 1");
  FieldInput f;
  f.mesh = io::readMesh(a.from);
  f.field = io::selectField(f.mesh, a.field, a.from);
  f.patch = patchMesh(f.mesh, a.from);
  f.hessians = fieldHessians(f.patch, f.field.values, a.hessian);
  return f;
}

AdaptRun adaptFile(AdaptArgs& a, const FieldInput& f, io::Report& report) {
  MeshArgs& m = a.mesh;
  if (m.options.dim == 0) m.options.dim = f.patch.dim;
  m.anisotropyGiven = true;  // the adapted metric's γ_a holds in the volume too
  if (!(a.error > 0) && !(a.targetNodes > 0)) a.targetNodes = static_cast<double>(f.mesh.nodes.size());
  PreparedRun prepared = prepareRun(m, report);
  AdaptRequest request;
  request.mesh = prepared.request;
  request.norm = a.norm;
  request.targetNodes = a.error > 0 ? 0 : a.targetNodes;
  request.error = a.error;
  AdaptRun run;
  try {
    run.result = adaptModel(prepared.input.model, f.patch, f.hessians, request);
  } catch (const FieldError& e) {
    throw InputError(a.from + ": field " + a.field + ": " + e.what());
  }
  run.input = std::move(prepared.input);
  reportResult(m, run.input.model, run.result.mesh, report);
  report.extra["adapt"] = adaptJson(a, f, run.result);
  return run;
}

}  // namespace aniso::app
