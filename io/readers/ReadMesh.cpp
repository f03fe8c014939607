// Cell type facts and the reader chosen by extension (ReadMesh.h).
#include "io/readers/ReadMesh.h"

#include "io/readers/Scanner.h"
#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"

namespace aniso::io {
namespace {

struct TypeInfo {
  const char* name;
  int dim, nodes;
};

constexpr TypeInfo kTypes[] = {
    {"point", 0, 1},       {"line", 1, 2},        {"line3", 1, 3},       {"triangle", 2, 3},
    {"triangle6", 2, 6},   {"quad", 2, 4},        {"quad8", 2, 8},       {"quad9", 2, 9},
    {"tet", 3, 4},         {"tet10", 3, 10},      {"hex", 3, 8},         {"hex20", 3, 20},
    {"hex27", 3, 27},      {"prism", 3, 6},       {"prism15", 3, 15},    {"prism18", 3, 18},
    {"pyramid", 3, 5},     {"pyramid13", 3, 13},  {"pyramid14", 3, 14},  {"polygon", 2, 0},
};

}  // namespace

const char* cellTypeName(CellType t) { return kTypes[static_cast<int>(t)].name; }
int cellDimension(CellType t) { return kTypes[static_cast<int>(t)].dim; }
int cellNodeCount(CellType t) { return kTypes[static_cast<int>(t)].nodes; }

namespace {

ReadMesh readByExtension(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".msh") return readMsh(path);
  if (ext == ".inp") return readInp(path);
  if (ext == ".vtu") return readVtu(path);
  if (ext == ".frd") return readFrd(path);
  if (ext == ".stl" || ext == ".obj" || ext == ".off") return readSurfaceWithOpenMesh(path);
  throw InputError(path + ": unknown mesh format (expected .msh .inp .vtu .frd .stl .obj .off)");
}

}  // namespace

ReadMesh readMesh(const std::string& path) {
  ReadMesh m;
  try {
    m = readByExtension(path);
  } catch (const InputError& e) {  // messages quote the file: keep them one printable line
    throw InputError(printable(e.what(), 400));
  }
  if (m.cellCount() == 0) throw InputError(path + ": no elements in the file");
  const int n = static_cast<int>(m.nodes.size());
  for (int v : m.conn)
    if (v < 0 || v >= n) throw InputError(path + ": an element refers to a node that does not exist");
  for (const Vec3& p : m.nodes)
    if (!p.allFinite()) throw InputError(path + ": a node has non-finite coordinates");
  return m;
}

}  // namespace aniso::io
