// anisomesh adapt MODEL --from MESH --field NAME -o OUT (issue 19): the options, then the
// run of tools/app/AdaptRun.h (the field's metric as point sources, the model meshed from
// the CAD, the count rounds: mesher/adapt/AdaptModel.h), written like `anisomesh mesh`.
// --transfer writes the field's array (all components) at the new nodes into the output
// (.msh / .vtu; mesher/adapt/FieldTransfer.h).
#include <chrono>

#include "mesher/adapt/FieldTransfer.h"
#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"
#include "tools/cli/AdaptCommand.h"

namespace aniso::cli {

CLI::App* addAdaptCommand(CLI::App& app, AdaptOptions& o) {
  AdaptArgs& a = o.args;
  a.mesh.options.sizing.anisotropy = 10;
  CLI::App* cmd = app.add_subcommand("adapt", "Mesh a CAD model adapted to a field of a solver's mesh (Lp metric)");
  cmd->add_option("MODEL", a.mesh.file, "STEP, IGES, BREP or .json analytic model")->required();
  cmd->add_option("--from", a.from, "The solver's mesh with the field: .msh .vtu .frd .inp")->required();
  cmd->add_option("--field", a.field, "NAME, NAME:x|y|z|N, tensors NAME:mises|p1|p2|p3")->required();
  cmd->add_option("-o,--output", a.mesh.output, "Output mesh: .msh .inp .vtu .stl .obj .off .unv")->required();
  cmd->add_option("--target-nodes", a.targetNodes, "Node count asked (default: that of --from)")->check(CLI::PositiveNumber);
  cmd->add_option("--error", a.error, "Lp interpolation error asked, instead of a node count")->check(CLI::PositiveNumber);
  cmd->add_option("--norm", a.norm, "p of the Lp norm the metric minimises")->check(CLI::Range(1.0, 1e6))->capture_default_str();
  cmd->add_option("--hessian", o.hessian, "Hessian recovery: ls (least squares) or l2 (double L2 projection)")
      ->check(CLI::IsMember({"ls", "l2"}))->capture_default_str();
  cmd->add_option("--dim", a.mesh.options.dim, "2 or 3 (default: that of the field's mesh)")->check(CLI::IsMember({2, 3}));
  cmd->add_option("--order", a.mesh.options.order, "Element order")->check(CLI::IsMember({1, 2}))->capture_default_str();
  cmd->add_flag("--binary", a.mesh.binary, "Binary output where the format has it");
  cmd->add_flag("--transfer", o.transfer, "Write the field (all its components) at the new nodes (.msh .vtu)");
  cmd->add_option("--report", a.mesh.report, "Write the JSON run report here");
  cmd->fallthrough();
  return cmd;
}

int runAdapt(const AdaptOptions& o) {
  AdaptArgs a = o.args;
  a.hessian = o.hessian == "l2" ? HessianMethod::DoubleL2 : HessianMethod::LeastSquares;
  const std::string ext = lowerExtension(a.mesh.output);
  if (o.transfer && ext != ".msh" && ext != ".vtu")
    throw InputError(a.mesh.output + ": --transfer writes the field into .msh or .vtu only");
  // the field first: a bad one fails before the model is read
  const app::FieldInput field = app::readField(a);
  return runGuarded(a.mesh, [&](MeshArgs& m, io::Report& report) {
    const auto t0 = std::chrono::steady_clock::now();
    a.mesh = m;  // with the time limit's token
    const app::AdaptRun run = app::adaptFile(a, field, report);
    const MeshResult& result = run.result.mesh;
    std::vector<io::NodeData> nodeData;
    if (o.transfer && result.meshed()) {
      const auto& nodes = (result.volumeRan ? result.volume.mesh.surface : result.surface.mesh).nodes;
      const TransferredField t = transferField(field.patch, field.field.arrayValues, field.field.components, nodes);
      report.extra["adapt"]["transfer"] = {{"array", field.field.arrayName},
                                           {"components", field.field.components},
                                           {"nodes_outside", t.outside},
                                           {"max_distance_outside", t.maxDistance}};
      nodeData.push_back({field.field.arrayName, field.field.components, t.values});
    }
    return writeRun(a.mesh, run.input.model, result, report, t0, nodeData);
  });
}

}  // namespace aniso::cli
