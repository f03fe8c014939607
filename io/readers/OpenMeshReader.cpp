// STL, OBJ and OFF through OpenMesh's readers, into a polygon soup: an importer of our own
// records every vertex and face as the reader hands them over, so faces that a halfedge
// mesh would refuse (non-manifold, duplicated, flipped) reach the check as they are in the
// file. OpenMesh's STL reader merges coincident vertices.
#include <OpenMesh/Core/IO/MeshIO.hh>

#include <sstream>

#include "io/readers/ReadMesh.h"
#include "io/readers/Scanner.h"
#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"

namespace aniso::io {
namespace {

using namespace OpenMesh;

class SoupImporter final : public IO::BaseImporter {
 public:
  std::vector<Vec3>& nodes;
  std::vector<std::vector<int>>& faces;
  SoupImporter(std::vector<Vec3>& n, std::vector<std::vector<int>>& f) : nodes(n), faces(f) {}

  VertexHandle add_vertex(const Vec3f& p) override { return add_vertex(Vec3d(p)); }
  VertexHandle add_vertex(const Vec3d& p) override {
    nodes.emplace_back(p[0], p[1], p[2]);
    return VertexHandle(static_cast<int>(nodes.size()) - 1);
  }
  VertexHandle add_vertex() override { return add_vertex(Vec3d(0, 0, 0)); }
  FaceHandle add_face(const VHandles& v) override {
    std::vector<int> f;
    for (const VertexHandle& h : v) f.push_back(h.idx());
    faces.push_back(std::move(f));
    return FaceHandle(static_cast<int>(faces.size()) - 1);
  }
  void set_point(VertexHandle v, const Vec3f& p) override {
    if (v.is_valid() && static_cast<std::size_t>(v.idx()) < nodes.size()) nodes[v.idx()] = Vec3(p[0], p[1], p[2]);
  }
  size_t n_vertices() const override { return nodes.size(); }
  size_t n_faces() const override { return faces.size(); }
  size_t n_edges() const override { return 0; }

  // Connectivity by halfedges, attributes and textures: not used by the check.
  HalfedgeHandle add_edge(VertexHandle, VertexHandle) override { return HalfedgeHandle(); }
  FaceHandle add_face(HalfedgeHandle) override { return FaceHandle(); }
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec2f>&) override {}
  void add_face_texcoords(FaceHandle, VertexHandle, const std::vector<Vec3f>&) override {}
  void set_face_texindex(FaceHandle, int) override {}
  void set_halfedge(VertexHandle, HalfedgeHandle) override {}
  void set_normal(VertexHandle, const Vec3f&) override {}
  void set_normal(VertexHandle, const Vec3d&) override {}
  void set_color(VertexHandle, const Vec3uc&) override {}
  void set_color(VertexHandle, const Vec4uc&) override {}
  void set_color(VertexHandle, const Vec3f&) override {}
  void set_color(VertexHandle, const Vec4f&) override {}
  void set_texcoord(VertexHandle, const Vec2f&) override {}
  void set_status(VertexHandle, const Attributes::StatusInfo&) override {}
  void set_next(HalfedgeHandle, HalfedgeHandle) override {}
  void set_face(HalfedgeHandle, FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HalfedgeHandle, const Vec2f&) override {}
  void set_texcoord(VertexHandle, const Vec3f&) override {}
  void set_texcoord(HalfedgeHandle, const Vec3f&) override {}
  void set_status(HalfedgeHandle, const Attributes::StatusInfo&) override {}
  void set_color(EdgeHandle, const Vec3uc&) override {}
  void set_color(EdgeHandle, const Vec4uc&) override {}
  void set_color(EdgeHandle, const Vec3f&) override {}
  void set_color(EdgeHandle, const Vec4f&) override {}
  void set_status(EdgeHandle, const Attributes::StatusInfo&) override {}
  void set_normal(FaceHandle, const Vec3f&) override {}
  void set_normal(FaceHandle, const Vec3d&) override {}
  void set_color(FaceHandle, const Vec3uc&) override {}
  void set_color(FaceHandle, const Vec4uc&) override {}
  void set_color(FaceHandle, const Vec3f&) override {}
  void set_color(FaceHandle, const Vec4f&) override {}
  void set_status(FaceHandle, const Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}
};

/// OpenMesh's streams are silenced while it reads: library code does not print.
class QuietOpenMesh {
 public:
  QuietOpenMesh() {
    omlog().disable();
    omerr().disable();
    omout().disable();
  }
  ~QuietOpenMesh() {
    omlog().enable();
    omerr().enable();
    omout().enable();
  }
};

/// The text without its '#' comment lines (ASCII OFF allows them).
std::string withoutComments(const std::string& text) {
  std::istringstream in(text);
  std::string out, line;
  while (std::getline(in, line)) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line[first] == '#') continue;
    out += line;
    out += '\n';
  }
  return out;
}

}  // namespace

ReadMesh readSurfaceWithOpenMesh(const std::string& path) {
  ReadMesh m;
  m.format = lowerExtension(path).substr(1);
  std::vector<std::vector<int>> faces;
  SoupImporter importer(m.nodes, faces);
  IO::Options options;
  bool ok = false;
  {
    const QuietOpenMesh quiet;
    const std::string data = readWholeFile(path);
    if (m.format == "off" && data.rfind("OFF BINARY", 0) != 0) {  // OpenMesh's OFF reader knows no comments
      std::istringstream in(withoutComments(data));
      ok = IO::IOManager().read(in, ".off", importer, options);
    } else {
      ok = IO::IOManager().read(path, importer, options);
    }
  }
  if (!ok) throw InputError(path + ": not a readable " + m.format + " file");
  for (const std::vector<int>& f : faces) {
    if (f.size() < 3) throw InputError(path + ": a face has fewer than 3 vertices");
    const CellType t = f.size() == 3 ? CellType::Triangle : f.size() == 4 ? CellType::Quad : CellType::Polygon;
    m.addCell(t, f.data(), static_cast<int>(f.size()));
  }
  return m;
}

}  // namespace aniso::io
