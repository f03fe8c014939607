#include "tools/app/MeshArgsCheck.h"

#include <filesystem>

#include "mesher/core/Error.h"
#include "mesher/core/Log.h"

namespace aniso::app {

void checkMeshArguments(const MeshArgs& a) {
  std::error_code ec;
  if (std::filesystem::is_directory(a.output, ec))
    throw InputError(a.output + ": is a directory; give the mesh file's name, e.g. -o " +
                     (std::filesystem::path(a.output) / "mesh.msh").string());
  if (a.options.quad && a.options.dim == 3)
    throw InputError(a.file + ": --quad makes a quad-dominant surface mesh (there are no hexahedra): "
                              "use --quad --dim 2, or drop --quad for tetrahedra");
}

int defaultDimension(const MeshArgs& a, int solids) {
  if (solids == 0) return 2;
  if (!a.options.quad) return 3;
  logNotice("--quad: a quad-dominant surface mesh of the solids (--dim 2 implied; --quad has no volume elements)");
  return 2;
}

}  // namespace aniso::app
