#pragma once
// The subcommands of the anisomesh program. Each returns the process exit code
// (0 ok, 2 bad input, 3 meshing failure) or throws InputError / MeshingError, which
// main() turns into a one-line message and the same codes.
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "cad/CadModel.h"
#include "io/MeshWriter.h"
#include "io/Report.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/sizing/UserSizing.h"
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
/// Called once the mesh is made, before it is written: data arrays at its nodes to write
/// with it (adapt --transfer); may add to the report's `extra` block.
using NodeDataHook = std::function<std::vector<io::NodeData>(const std::vector<Vec3>& nodes, nlohmann::ordered_json& extra)>;
/// Meshes, writes, and prints the run's summary — or, given `report`, keeps the summary in
/// it for the caller to print (adapt prints only its last mesh's).
int runMesh(const MeshArgs& args, const NodeDataHook& nodeData = {}, io::Report* report = nullptr);

struct AdaptArgs {
  MeshArgs mesh;           ///< model, output, report, order, sizing options
  std::string from;        ///< the solver's mesh with the field (.msh .vtu .frd ...)
  std::string field;       ///< NAME or NAME:COMPONENT (io/readers/fields/NodalField.h)
  double targetNodes = 0;  ///< --target-nodes (default: the node count of --from)
  double error = 0;        ///< --error
  double norm = 2;         ///< --norm p; γ_a is mesh.options.sizing.anisotropy (default 10)
  std::string hessian = "ls";  ///< --hessian: ls (least squares) or l2 (double L2 projection)
  double metricTarget = 0;     ///< the vertex count the metric is scaled to (set by runAdapt)
  double firstNodes = 0;       ///< the first mesh's count, when it was made again
  bool transfer = false;       ///< --transfer: the field's array interpolated to the new nodes
};
/// anisomesh adapt (AdaptCommand.cpp): the mesh of MODEL adapted to a field of a solver's
/// mesh (issue 19).
int runAdapt(const AdaptArgs& args);

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
