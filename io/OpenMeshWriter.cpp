// OBJ and OFF through OpenMesh: the triangles and quads of the surface mesh, corner nodes
// only (mid-edge and interior nodes are left out).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "io/FormatWriters.h"
#include "mesher/core/Error.h"

namespace aniso::io {

void writeOpenMeshFormat(const OutputMesh& mesh, const std::string& path, const WriteOptions& opt) {
  using Mesh = OpenMesh::PolyMesh_ArrayKernelT<>;
  const SurfaceMesh& sm = mesh.surface;
  Mesh m;
  std::vector<Mesh::VertexHandle> vh(sm.nodes.size());
  auto vertex = [&](int n) {
    if (!vh[n].is_valid()) vh[n] = m.add_vertex(Mesh::Point(sm.nodes[n].x(), sm.nodes[n].y(), sm.nodes[n].z()));
    return vh[n];
  };
  // A face OpenMesh refuses as non-manifold (three faces on an edge, e.g. at an interface
  // between solids) is added on its own copies of the vertices: the formats are soups.
  auto addFace = [&](std::initializer_list<int> nodes) {
    std::vector<Mesh::VertexHandle> f;
    for (int n : nodes) f.push_back(vertex(n));
    if (m.add_face(f).is_valid()) return;
    f.clear();
    for (int n : nodes) f.push_back(m.add_vertex(Mesh::Point(sm.nodes[n].x(), sm.nodes[n].y(), sm.nodes[n].z())));
    m.add_face(f);
  };
  for (const auto& t : sm.triangles) addFace({t[0], t[1], t[2]});
  for (const auto& q : sm.quads) addFace({q[0], q[1], q[2], q[3]});
  const std::filesystem::path target(path);
  // OpenMesh picks the format from the name's extension: keep it on the temporary file.
  const std::string temp = (target.parent_path() / (".tmp" + std::to_string(::getpid()) + "_" +
                                                     target.filename().string())).string();
  OpenMesh::IO::Options o;
  if (opt.binary) o += OpenMesh::IO::Options::Binary;
  bool ok = false;
  omlog().disable();  // OpenMesh logs every file it writes: library code stays silent
  try {
    ok = OpenMesh::IO::write_mesh(m, temp, o);
  } catch (const std::exception&) {
    ok = false;
  }
  omlog().enable();
  std::error_code ec;
  if (ok) std::filesystem::rename(temp, target, ec);
  if (!ok || ec) {
    std::remove(temp.c_str());
    throw MeshingError(path + ": cannot write the mesh");
  }
}

}  // namespace aniso::io
