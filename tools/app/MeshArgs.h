#pragma once
// MeshArgs — a mesh run as a program asks for it (the CLI's `mesh` command, the Python
// module): the model file, the options as given, where the mesh and the report go.
// MeshRun.h turns it into meshModel's request with the program's defaults.
#include <string>

#include "cad/CadModel.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/model/Model.h"
#include "mesher/sizing/UserSizing.h"

namespace aniso::app {

struct MeshArgs {
  std::string file;
  std::string output;
  std::string report;
  bool binary = false;
  int mshVersion = 41;  ///< MSH output: 41 or 22 (--msh-version 4.1 | 2.2)
  bool fragment = true;
  cad::OverlapPolicy overlaps = cad::OverlapPolicy::Merge;  ///< --overlaps
  MeshOptions options;
  /// --anisotropy was given. Without it the mesh is isotropic (γ_a = 1): FE solvers want
  /// elements well shaped in space (the tetrahedra on a stretched boundary triangle are
  /// stretched too; shell elements want triangles near equilateral, Gmsh's default), and
  /// the surface repair stage is Euclidean. The thesis' default γ_a = 5 on request.
  bool anisotropyGiven = false;
  /// --time-limit S: the run stops (status failed, exit 3, no mesh) after S seconds; 0 = none.
  double timeLimit = 0;
};

}  // namespace aniso::app
