// Gmsh MSH 2.2 writer, ASCII or binary (format reference: the Gmsh manual, "MSH file format
// version 2 (Legacy)"). Every element carries two tags: its physical group (the face id
// for triangles and quads, the solid id for tetrahedra, as in $PhysicalNames) and its
// elementary entity (the same ids). MSH 2 gives an element one physical group: the
// triangles and quads of a face in a named face group (groupNames) are written once more
// after all the others, with new element numbers and the group's tag, as Gmsh itself
// writes an element of several physical groups in this version.
#include <ostream>
#include <vector>

#include "io/AtomicFile.h"
#include "io/ElementOrder.h"
#include "io/FormatWriters.h"
#include "io/MshOut.h"

namespace aniso::io {

void writeMsh22(const OutputMesh& m, const std::string& path, const WriteOptions& opt) {
  AtomicFile file(path, opt.binary);
  std::ostream& o = file.stream();
  MshOut w(o, opt.binary);
  writeMshHeader(o, "2.2", opt.binary, m);

  const std::vector<Vec3>& p = m.nodes();
  w.text("$Nodes\n");
  w.asciiLine(p.size());
  for (size_t i = 0; i < p.size(); ++i) {
    w.value<int>(static_cast<int>(i) + 1);
    for (int k = 0; k < 3; ++k) w.value<double>(p[i][k]);
    w.endLine();
  }
  w.endSection("$EndNodes");

  // Elements: per face its triangles then its quads, then per solid its tetrahedra.
  const auto tris = m.byEntity(Shape::Triangle), quads = m.byEntity(Shape::Quad), tets = m.byEntity(Shape::Tet);
  struct Block {
    Shape shape;
    int entity, physical;  // 0-based entity, physical tag
    const std::vector<int>* elements;
  };
  std::vector<Block> blocks;
  const auto faceBlocks = [&](int f, int physical) {
    if (!tris[f].empty()) blocks.push_back({Shape::Triangle, f, physical, &tris[f]});
    if (!quads[f].empty()) blocks.push_back({Shape::Quad, f, physical, &quads[f]});
  };
  for (size_t f = 0; f < tris.size(); ++f) faceBlocks(static_cast<int>(f), static_cast<int>(f) + 1);
  for (size_t s = 0; s < tets.size(); ++s)
    if (!tets[s].empty()) blocks.push_back({Shape::Tet, static_cast<int>(s), static_cast<int>(s) + 1, &tets[s]});
  const std::vector<FaceGroup> groups = groupNames(m.model).faces;
  for (size_t k = 0; k < groups.size(); ++k)
    for (const int f : groups[k].faces) faceBlocks(f, faceGroupTag(m.model, k));
  std::size_t count = 0;
  for (const Block& b : blocks) count += b.elements->size();
  w.text("$Elements\n");
  w.asciiLine(count);
  int tag = 1;
  std::array<int, 10> nodes{};
  for (const Block& b : blocks) {
    const bool q = m.quadratic(b.shape);
    const int type = gmshElementType(b.shape, q);
    const auto& perm = b.shape == Shape::Tet && q ? order::kGmshTet10 : order::kIdentity;
    if (opt.binary) {  // binary header: type, number of elements, number of tags
      w.value<int>(type);
      w.value<int>(static_cast<int>(b.elements->size()));
      w.value<int>(2);
    }
    for (int e : *b.elements) {
      const int k = m.elementNodes(b.shape, e, nodes);
      w.value<int>(tag++);
      if (!opt.binary) {
        w.value<int>(type);
        w.value<int>(2);
      }
      w.value<int>(b.physical);
      w.value<int>(b.entity + 1);
      for (int j = 0; j < k; ++j) w.value<int>(nodes[perm[j]] + 1);
      w.endLine();
    }
  }
  w.endSection("$EndElements");
  for (const NodeData& d : opt.nodeData) writeMshNodeData(w, d);
  file.commit();
}

}  // namespace aniso::io
