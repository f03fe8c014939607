// writeSurfaceMesh / writeVolumeMesh: the format from the extension (io/MeshWriter.h).
#include "io/FormatWriters.h"
#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"

namespace aniso::io {
namespace {

void write(const OutputMesh& m, const std::string& path, const WriteOptions& opt) {
  if (opt.mshVersion != 41 && opt.mshVersion != 22)
    throw InputError(path + ": unknown MSH version " + std::to_string(opt.mshVersion) + " (expected 4.1 or 2.2)");
  const std::string ext = lowerExtension(path);
  const bool known = ext == ".msh" || ext == ".inp" || ext == ".vtu" || ext == ".unv" || ext == ".stl" ||
                     ext == ".obj" || ext == ".off";
  if (!known) throw InputError(path + ": unknown output format (expected .msh .inp .vtu .unv .stl .obj .off)");
  m.check(path);
  for (const NodeData& d : opt.nodeData) {
    if (ext != ".msh" && ext != ".vtu") throw InputError(path + ": node data (" + d.name + ") is written to .msh and .vtu only");
    if (d.components < 1 || d.values.size() != m.nodes().size() * static_cast<std::size_t>(d.components))
      throw MeshingError(path + ": node data " + d.name + " has " + std::to_string(d.values.size()) + " values for " +
                         std::to_string(m.nodes().size()) + " nodes");
  }
  if (ext == ".msh") return opt.mshVersion == 22 ? writeMsh22(m, path, opt) : writeMsh41(m, path, opt);
  if (ext == ".inp") return writeInp(m, path);
  if (ext == ".vtu") return writeVtu(m, path, opt);
  if (ext == ".unv") return writeUnv(m, path);
  if (ext == ".stl") return writeStl(m, path, opt);
  writeOpenMeshFormat(m, path, opt);
}

}  // namespace

void writeSurfaceMesh(const Model& model, const SurfaceMesh& mesh, const std::string& path, const WriteOptions& opt) {
  write(OutputMesh(model, mesh), path, opt);
}

void writeVolumeMesh(const Model& model, const VolumeMesh& mesh, const std::string& path, const WriteOptions& opt) {
  write(OutputMesh(model, mesh), path, opt);
}

}  // namespace aniso::io
