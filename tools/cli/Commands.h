#pragma once
// The subcommands of the anisomesh program. Each returns the process exit code
// (0 ok, 2 bad input, 3 meshing failure) or throws InputError / MeshingError, which
// main() turns into a one-line message and the same codes.
#include <chrono>
#include <functional>
#include <string>
#include <vector>


#include "cad/CadModel.h"
#include "io/MeshWriter.h"
#include "io/Report.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/pipeline/MeshResult.h"
#include "tools/app/AdaptRun.h"
#include "tools/app/MeshArgs.h"

namespace aniso::cli {

struct InfoArgs {
  std::string file;
  bool json = false;
  bool faces = false;  ///< --faces: every face and edge of the prepared model (FaceListing.h)
  bool fragment = true;
  cad::OverlapPolicy overlaps = cad::OverlapPolicy::Merge;  ///< --overlaps
};
int runInfo(const InfoArgs& args);

using app::MeshArgs;
/// Meshes, writes, and prints the run's summary.
int runMesh(const MeshArgs& args);

/// What mesh and adapt share (MeshCommand.cpp): the option checks that need no model, the
/// --time-limit token, `body` (which meshes and calls writeRun), then the run's summary
/// printed. A time limit reached writes the failed report and throws MeshingError.
int runGuarded(const MeshArgs& args, const std::function<int(MeshArgs&, io::Report&)>& body);

/// Writes the mesh (with `nodeData` arrays at its nodes, .msh / .vtu) and the report graded
/// from its problems; a result with no mesh writes the failed report and throws
/// MeshingError naming the first failure. `t0`: when the run began (the report's total).
int writeRun(const MeshArgs& args, const Model& model, const MeshResult& result, io::Report& report,
             std::chrono::steady_clock::time_point t0, const std::vector<io::NodeData>& nodeData);

using app::AdaptArgs;
/// anisomesh adapt (AdaptCommand.cpp): the mesh of MODEL adapted to a field of a solver's
/// mesh (issue 19).
struct AdaptOptions {
  AdaptArgs args;
  std::string hessian = "ls";  ///< --hessian: ls (least squares) or l2 (double L2 projection)
  bool transfer = false;       ///< --transfer: the field's array interpolated to the new nodes
};
int runAdapt(const AdaptOptions& options);

struct SizingArgs {
  std::string file;
  std::string output;
  int face = 0;  ///< 1-based; 0 = every face, mapped to 3D
  bool fragment = true;
  std::string sizingFile;
  SizingParameters params;
};
int runSizing(const SizingArgs& args);

struct CheckArgs {
  std::string file;
  bool json = false;
};
/// Reads a mesh (MSH, INP, VTU, STL, OBJ, OFF) and reports counts, surface topology,
/// validity and quality; 0 valid, 3 invalid (io/readers/MeshCheck.h).
int runCheck(const CheckArgs& args);

/// Output formats the mesh command writes, by extension.
bool isKnownOutputExtension(const std::string& path);

}  // namespace aniso::cli
