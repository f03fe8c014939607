#pragma once
// meshFile — the mesh run of a program (the CLI's `mesh`, the Python module) up to the mesh
// in memory: the sizing file and the model read, the program's defaults resolved, meshModel
// (mesher/pipeline/Pipeline.h) called and the run report filled. Writing the mesh and the
// report, and what the terminal shows, are the caller's. The same MeshArgs give the same
// mesh, byte for byte, through either program.
#include <memory>
#include <string>

#include "io/Report.h"
#include "mesher/pipeline/MeshRequest.h"
#include "mesher/pipeline/MeshResult.h"
#include "tools/app/MeshArgs.h"
#include "tools/app/ModelInput.h"

namespace aniso::app {

struct MeshRun {
  ModelInput input;    ///< the model as read and prepared
  MeshResult result;   ///< result.meshed() false: no mesh (failureMessage says why)
};

/// A run read and resolved, up to meshModel's call (what meshFile and adaptFile share).
struct PreparedRun {
  ModelInput input;
  MeshRequest request;  ///< request.analytic points into `analytic`
  std::unique_ptr<ControlSpace2d> analytic;
};

/// meshFile's first half: the checks, the sizing file and the model read, the defaults
/// resolved into `args` and `request`, `report` filled with the input, options and model.
PreparedRun prepareRun(MeshArgs& args, io::Report& report);

/// meshFile's last half: `report` gets the mesh's counts, quality and sizing.
void reportResult(const MeshArgs& args, const Model& model, const MeshResult& result, io::Report& report);

/// Checks the options that need no model (checkMeshArguments, the sizing's check), reads
/// args.options.sizingFile and args.file, resolves into `args` what the user left open:
/// options.dim (defaultDimension), the anisotropy 1 when not given (MeshArgs::anisotropyGiven)
/// and the element budget (elementBudget); then meshes. `report` is filled as the run goes
/// (input, options, model, times, problems; after meshing the counts, quality and sizing),
/// so a caller catching Cancelled still has what was done; its status and total time are
/// left to the caller (gradeRun). Throws InputError (bad file or options, nothing to mesh
/// in the asked dimension) and Cancelled (options.cancel).
MeshRun meshFile(MeshArgs& args, io::Report& report);

/// The one line of a run that made no mesh: "FILE: [invalid model topology: ]ENTITY: detail"
/// naming the first failed problem (else the first degraded one).
std::string failureMessage(const std::string& file, const io::Report& report, PipelineStop stop);

/// "N entities left out, M meshed with shortcomings; first: ENTITY: detail" for a degraded run.
std::string degradedSummary(const io::Report& report);

}  // namespace aniso::app
