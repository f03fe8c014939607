// Gmsh MSH 4.1 writer for surface meshes (format reference: the Gmsh manual, "MSH file
// format version 4.1").
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <ostream>
#include <vector>

#include "io/AtomicFile.h"
#include "io/MeshWriter.h"
#include "mesher/core/Error.h"

namespace aniso::io {
namespace {

/// Writes either ASCII tokens or raw binary values, as MSH 4.1 asks for each section.
class MshOut {
 public:
  MshOut(std::ostream& o, bool binary) : o_(o), binary_(binary) { o_ << std::setprecision(17); }
  template <class T>
  void value(T v, char sep = ' ') {
    if (binary_) {
      o_.write(reinterpret_cast<const char*>(&v), sizeof(T));
    } else {
      o_ << v << sep;
    }
  }
  void endLine() {
    if (!binary_) o_ << '\n';
  }
  void text(const char* s) { o_ << s; }
  bool binary() const { return binary_; }

 private:
  std::ostream& o_;
  bool binary_;
};

Box3 edgeBox(const Model& model, int e, const SurfaceMesh& mesh, const std::vector<std::vector<int>>& edgeNodes) {
  Box3 b;
  const ModelEdge& me = model.edges[e];
  if (me.v0 >= 0) b.add(model.vertices[me.v0].p);
  if (me.v1 >= 0) b.add(model.vertices[me.v1].p);
  for (int n : edgeNodes[e]) b.add(mesh.nodes[n]);
  return b;
}

}  // namespace

void writeMsh41(const Model& model, const SurfaceMesh& mesh, const std::string& path, const WriteOptions& opt) {
  const int nv = static_cast<int>(model.vertices.size());
  const int ne = static_cast<int>(model.edges.size());
  const int nf = static_cast<int>(model.faces.size());
  // Nodes grouped by the entity they lie on (dim, index).
  std::vector<std::vector<int>> vertexNodes(nv), edgeNodes(ne), faceNodes(nf);
  for (size_t i = 0; i < mesh.nodes.size(); ++i) {
    const NodeOn& on = mesh.nodeOn[i];
    switch (on.kind) {
      case NodeOn::Kind::Vertex: vertexNodes.at(on.entity).push_back(static_cast<int>(i)); break;
      case NodeOn::Kind::Edge: edgeNodes.at(on.entity).push_back(static_cast<int>(i)); break;
      case NodeOn::Kind::Face: faceNodes.at(on.entity).push_back(static_cast<int>(i)); break;
      case NodeOn::Kind::Solid: break;  // no volume nodes in a surface mesh
    }
  }
  std::vector<std::vector<int>> faceTris(nf);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) faceTris.at(mesh.triangleFace[t]).push_back(static_cast<int>(t));
  std::vector<std::uint8_t> faceUsed(nf, 0);
  for (int f = 0; f < nf; ++f) faceUsed[f] = !faceTris[f].empty();

  AtomicFile file(path, opt.binary);
  std::ostream& o = file.stream();
  MshOut w(o, opt.binary);
  o << "$MeshFormat\n4.1 " << (opt.binary ? 1 : 0) << " 8\n";
  if (opt.binary) {
    const int one = 1;
    o.write(reinterpret_cast<const char*>(&one), sizeof one);
    o << '\n';
  }
  o << "$EndMeshFormat\n";

  // Physical groups: one per meshed face, tag = face id.
  int nPhys = 0;
  for (int f = 0; f < nf; ++f) nPhys += faceUsed[f];
  o << "$PhysicalNames\n" << nPhys << '\n';
  for (int f = 0; f < nf; ++f)
    if (faceUsed[f]) o << "2 " << f + 1 << " \"FACE" << f + 1 << "\"\n";
  o << "$EndPhysicalNames\n";

  // Entities: all model vertices and edges, the meshed faces.
  o << "$Entities\n";
  w.value<std::size_t>(nv);
  w.value<std::size_t>(ne);
  w.value<std::size_t>(nPhys);
  w.value<std::size_t>(0);
  w.endLine();
  for (int v = 0; v < nv; ++v) {
    w.value<int>(v + 1);
    for (int k = 0; k < 3; ++k) w.value<double>(model.vertices[v].p[k]);
    w.value<std::size_t>(0);
    w.endLine();
  }
  for (int e = 0; e < ne; ++e) {
    const Box3 b = edgeBox(model, e, mesh, edgeNodes);
    w.value<int>(e + 1);
    for (int k = 0; k < 3; ++k) w.value<double>(b.lo[k]);
    for (int k = 0; k < 3; ++k) w.value<double>(b.hi[k]);
    w.value<std::size_t>(0);
    const ModelEdge& me = model.edges[e];
    const bool two = me.v0 >= 0 && me.v1 >= 0 && me.v0 != me.v1;
    w.value<std::size_t>(me.v0 < 0 ? 0 : (two ? 2 : 1));
    if (me.v0 >= 0) w.value<int>(me.v0 + 1);
    if (two) w.value<int>(-(me.v1 + 1));
    w.endLine();
  }
  for (int f = 0; f < nf; ++f) {
    if (!faceUsed[f]) continue;
    Box3 b;
    for (int t : faceTris[f])
      for (int n : mesh.triangles[t]) b.add(mesh.nodes[n]);
    std::vector<int> bounding;
    for (const Loop& loop : model.faces[f].loops)
      for (const EdgeUse& u : loop.uses) {
        const int tag = (u.edge + 1) * (u.reversed ? -1 : 1);
        if (std::find(bounding.begin(), bounding.end(), tag) == bounding.end() &&
            std::find(bounding.begin(), bounding.end(), -tag) == bounding.end())
          bounding.push_back(tag);
      }
    w.value<int>(f + 1);
    for (int k = 0; k < 3; ++k) w.value<double>(b.lo[k]);
    for (int k = 0; k < 3; ++k) w.value<double>(b.hi[k]);
    w.value<std::size_t>(1);
    w.value<int>(f + 1);
    w.value<std::size_t>(bounding.size());
    for (int tag : bounding) w.value<int>(tag);
    w.endLine();
  }
  o << (opt.binary ? "\n" : "") << "$EndEntities\n";

  // Nodes: one block per entity holding nodes; tags are node index + 1.
  struct Block {
    int dim, tag;
    const std::vector<int>* nodes;
  };
  std::vector<Block> blocks;
  for (int v = 0; v < nv; ++v)
    if (!vertexNodes[v].empty()) blocks.push_back({0, v + 1, &vertexNodes[v]});
  for (int e = 0; e < ne; ++e)
    if (!edgeNodes[e].empty()) blocks.push_back({1, e + 1, &edgeNodes[e]});
  for (int f = 0; f < nf; ++f)
    if (!faceNodes[f].empty()) blocks.push_back({2, f + 1, &faceNodes[f]});
  const std::size_t nn = mesh.nodes.size();
  o << "$Nodes\n";
  w.value<std::size_t>(blocks.size());
  w.value<std::size_t>(nn);
  w.value<std::size_t>(nn ? 1 : 0);
  w.value<std::size_t>(nn);
  w.endLine();
  for (const Block& b : blocks) {
    w.value<int>(b.dim);
    w.value<int>(b.tag);
    w.value<int>(0);
    w.value<std::size_t>(b.nodes->size());
    w.endLine();
    for (int n : *b.nodes) {
      w.value<std::size_t>(static_cast<std::size_t>(n) + 1);
      w.endLine();
    }
    for (int n : *b.nodes) {
      for (int k = 0; k < 3; ++k) w.value<double>(mesh.nodes[n][k]);
      w.endLine();
    }
  }
  o << (opt.binary ? "\n" : "") << "$EndNodes\n";

  // Elements: 3-node triangles (type 2), one block per face; tags in face order.
  const std::size_t nt = mesh.triangles.size();
  o << "$Elements\n";
  w.value<std::size_t>(nPhys);
  w.value<std::size_t>(nt);
  w.value<std::size_t>(nt ? 1 : 0);
  w.value<std::size_t>(nt);
  w.endLine();
  std::size_t tag = 1;
  for (int f = 0; f < nf; ++f) {
    if (!faceUsed[f]) continue;
    w.value<int>(2);
    w.value<int>(f + 1);
    w.value<int>(2);
    w.value<std::size_t>(faceTris[f].size());
    w.endLine();
    for (int t : faceTris[f]) {
      w.value<std::size_t>(tag++);
      for (int n : mesh.triangles[t]) w.value<std::size_t>(static_cast<std::size_t>(n) + 1);
      w.endLine();
    }
  }
  o << (opt.binary ? "\n" : "") << "$EndElements\n";
  file.commit();
}

}  // namespace aniso::io
