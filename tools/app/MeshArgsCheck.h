#pragma once
// Checks of the mesh command's arguments that read no model (InputError, exit 2, one line
// naming the argument and the fix), and the dimension a run takes when --dim is not given.
#include "tools/app/MeshArgs.h"

namespace aniso::app {

/// -o names a directory, or --quad is asked with --dim 3 (quad-dominant meshes are
/// surface meshes: there are no hexahedra): InputError with the fix.
void checkMeshArguments(const MeshArgs& args);

/// The dimension when --dim is not given: 3 for a model with solids, else 2; with --quad
/// always 2 (the quad-dominant surface of the solids), and a notice says so.
int defaultDimension(const MeshArgs& args, int solids);

}  // namespace aniso::app
