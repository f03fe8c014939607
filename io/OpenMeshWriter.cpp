// STL, OBJ and OFF through OpenMesh.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "io/MeshWriter.h"
#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"

namespace aniso::io {

void writeOpenMeshFormat(const SurfaceMesh& mesh, const std::string& path, const WriteOptions& opt) {
  using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;
  Mesh m;
  std::vector<Mesh::VertexHandle> vh;
  vh.reserve(mesh.nodes.size());
  for (const Vec3& p : mesh.nodes) vh.push_back(m.add_vertex(Mesh::Point(p.x(), p.y(), p.z())));
  // STL is a triangle soup: a triangle OpenMesh refuses as non-manifold (three faces on an
  // edge, e.g. at an interface) is added on its own copies of the vertices.
  for (const auto& t : mesh.triangles) {
    Mesh::FaceHandle f = m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
    if (!f.is_valid()) {
      std::vector<Mesh::VertexHandle> c;
      for (int n : t) c.push_back(m.add_vertex(Mesh::Point(mesh.nodes[n].x(), mesh.nodes[n].y(), mesh.nodes[n].z())));
      m.add_face(c);
    }
  }
  const std::filesystem::path target(path);
  // OpenMesh picks the format from the name's extension: keep it on the temporary file.
  const std::string temp = (target.parent_path() / (".tmp" + std::to_string(::getpid()) + "_" +
                                                     target.filename().string())).string();
  OpenMesh::IO::Options o;
  if (opt.binary) o += OpenMesh::IO::Options::Binary;
  bool ok = false;
  try {
    ok = OpenMesh::IO::write_mesh(m, temp, o);
  } catch (const std::exception&) {
    ok = false;
  }
  std::error_code ec;
  if (ok) std::filesystem::rename(temp, target, ec);
  if (!ok || ec) {
    std::remove(temp.c_str());
    throw MeshingError(path + ": cannot write the mesh");
  }
}

void writeSurfaceMesh(const Model& model, const SurfaceMesh& mesh, const std::string& path, const WriteOptions& opt) {
  const std::string ext = lowerExtension(path);
  if (ext == ".msh") return writeMsh41(model, mesh, path, opt);
  if (ext == ".stl" || ext == ".obj" || ext == ".off") return writeOpenMeshFormat(mesh, path, opt);
  throw InputError(path + ": this output format is not written yet for surface meshes");
}

}  // namespace aniso::io
