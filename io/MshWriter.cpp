// Gmsh MSH 4.1 writer (format reference: the Gmsh manual, "MSH file format version 4.1").
#include <algorithm>
#include <cstdint>
#include <ostream>
#include <vector>

#include "io/AtomicFile.h"
#include "io/ElementOrder.h"
#include "io/FormatWriters.h"
#include "io/MshOut.h"
#include "mesher/core/Error.h"

namespace aniso::io {

int gmshElementType(Shape s, bool quadratic) {
  switch (s) {
    case Shape::Triangle: return quadratic ? 9 : 2;
    case Shape::Quad: return quadratic ? 16 : 3;
    case Shape::Tet: return quadratic ? 11 : 4;
  }
  return 0;
}

namespace {

/// Nodes grouped by the model entity they lie on: [kind][entity] -> node indices.
std::array<std::vector<std::vector<int>>, 4> nodesByEntity(const OutputMesh& m) {
  std::array<std::vector<std::vector<int>>, 4> by;
  by[0].resize(m.model.vertices.size());
  by[1].resize(m.model.edges.size());
  by[2].resize(m.model.faces.size());
  by[3].resize(m.model.solids.size());
  for (size_t i = 0; i < m.surface.nodeOn.size(); ++i) {
    const NodeOn& on = m.surface.nodeOn[i];
    by[static_cast<int>(on.kind)][on.entity].push_back(static_cast<int>(i));
  }
  return by;
}

/// $Entities: every model vertex and edge; the faces and solids holding elements (with
/// their physical group) or nodes (without).
void writeEntities(const OutputMesh& m, MshOut& w,
                   const std::array<std::vector<std::vector<int>>, 4>& byEntity) {
  const Model& model = m.model;
  const std::vector<Vec3>& p = m.nodes();
  const std::vector<bool> meshedFaces = m.meshedFaces(), meshedSolids = m.meshedSolids();
  std::vector<bool> faces(model.faces.size()), solids(model.solids.size());
  for (size_t f = 0; f < faces.size(); ++f) faces[f] = meshedFaces[f] || !byEntity[2][f].empty();
  for (size_t s = 0; s < solids.size(); ++s) solids[s] = meshedSolids[s] || !byEntity[3][s].empty();
  const auto nf = std::count(faces.begin(), faces.end(), true);
  const auto ns = std::count(solids.begin(), solids.end(), true);
  w.text("$Entities\n");
  w.value<std::size_t>(model.vertices.size());
  w.value<std::size_t>(model.edges.size());
  w.value<std::size_t>(static_cast<std::size_t>(nf));
  w.value<std::size_t>(static_cast<std::size_t>(ns));
  w.endLine();
  for (size_t v = 0; v < model.vertices.size(); ++v) {
    w.value<int>(static_cast<int>(v) + 1);
    for (int k = 0; k < 3; ++k) w.value<double>(model.vertices[v].p[k]);
    w.value<std::size_t>(0);
    w.endLine();
  }
  auto box = [&](const Box3& b) {
    for (int k = 0; k < 3; ++k) w.value<double>(b.empty() ? 0.0 : b.lo[k]);
    for (int k = 0; k < 3; ++k) w.value<double>(b.empty() ? 0.0 : b.hi[k]);
  };
  // A surface or volume: its box, its physical group (same tag) if meshed and the named
  // groups it is in, its bounding entities.
  auto bounded = [&](size_t index, const Box3& b, bool physical, const std::vector<int>& named,
                     const std::vector<int>& bounding) {
    w.value<int>(static_cast<int>(index) + 1);
    box(b);
    w.value<std::size_t>(physical ? 1 + named.size() : 0);
    if (physical) w.value<int>(static_cast<int>(index) + 1);
    if (physical)
      for (const int tag : named) w.value<int>(tag);
    w.value<std::size_t>(bounding.size());
    for (int tag : bounding) w.value<int>(tag);
    w.endLine();
  };
  for (size_t e = 0; e < model.edges.size(); ++e) {
    const ModelEdge& me = model.edges[e];
    Box3 b;
    if (me.v0 >= 0) b.add(model.vertices[me.v0].p);
    if (me.v1 >= 0) b.add(model.vertices[me.v1].p);
    for (int n : byEntity[1][e]) b.add(p[n]);
    w.value<int>(static_cast<int>(e) + 1);
    box(b);
    w.value<std::size_t>(0);
    const bool two = me.v0 >= 0 && me.v1 >= 0 && me.v0 != me.v1;
    w.value<std::size_t>(me.v0 < 0 ? 0 : (two ? 2 : 1));
    if (me.v0 >= 0) w.value<int>(me.v0 + 1);
    if (two) w.value<int>(-(me.v1 + 1));
    w.endLine();
  }
  std::vector<Box3> faceBox(model.faces.size());
  std::array<int, 10> nodes{};
  for (Shape s : {Shape::Triangle, Shape::Quad})
    for (int i = 0, n = m.count(s); i < n; ++i) {
      const int k = m.elementNodes(s, i, nodes);
      for (int j = 0; j < k; ++j) faceBox[m.entityOf(s, i)].add(p[nodes[j]]);
    }
  for (size_t f = 0; f < faceBox.size(); ++f)
    for (int n : byEntity[2][f]) faceBox[f].add(p[n]);
  std::vector<std::vector<int>> faceGroups(model.faces.size());  // the named groups' tags of each face
  const std::vector<FaceGroup> groups = groupNames(model).faces;
  for (size_t k = 0; k < groups.size(); ++k)
    for (const int f : groups[k].faces) faceGroups[static_cast<size_t>(f)].push_back(faceGroupTag(model, k));
  for (size_t f = 0; f < model.faces.size(); ++f) {
    if (!faces[f]) continue;
    std::vector<int> bounding;
    for (const Loop& loop : model.faces[f].loops)
      for (const EdgeUse& u : loop.uses) {
        const int tag = (u.edge + 1) * (u.reversed ? -1 : 1);
        if (std::find(bounding.begin(), bounding.end(), tag) == bounding.end() &&
            std::find(bounding.begin(), bounding.end(), -tag) == bounding.end())
          bounding.push_back(tag);
      }
    bounded(f, faceBox[f], meshedFaces[f], faceGroups[f], bounding);
  }
  std::vector<Box3> solidBox(model.solids.size());
  {
    // Each node once per solid (seen: the last solid it was added to; a node of several
    // solids is added again when the solid changes — the same box).
    std::vector<int> seen(m.count(Shape::Tet) > 0 ? p.size() : 0, -1);
    for (int i = 0, n = m.count(Shape::Tet); i < n; ++i) {
      const int solid = m.volume->tetSolid[i];
      for (int v : m.volume->tets[i])
        if (seen[v] != solid) {
          seen[v] = solid;
          solidBox[solid].add(p[v]);
        }
    }
  }
  for (size_t s = 0; s < solidBox.size(); ++s)
    for (int n : byEntity[3][s]) solidBox[s].add(p[n]);
  for (size_t s = 0; s < model.solids.size(); ++s) {
    if (!solids[s]) continue;
    std::vector<int> bounding;
    const ModelSolid& ms = model.solids[s];
    std::vector<int> shells{ms.outerShell};
    shells.insert(shells.end(), ms.voidShells.begin(), ms.voidShells.end());
    for (int sh : shells) {
      if (sh < 0) continue;
      for (const FaceUse& fu : model.shells[sh].faces)
        if (faces[fu.face]) bounding.push_back((fu.face + 1) * (fu.reversed ? -1 : 1));
    }
    bounded(s, solidBox[s], meshedSolids[s], {}, bounding);
  }
  w.endSection("$EndEntities");
}

void writeNodes(const OutputMesh& m, MshOut& w,
                const std::array<std::vector<std::vector<int>>, 4>& byEntity) {
  std::size_t blocks = 0;
  for (const auto& kind : byEntity)
    for (const auto& list : kind) blocks += !list.empty();
  const std::size_t nn = m.nodes().size();
  w.text("$Nodes\n");
  w.value<std::size_t>(blocks);
  w.value<std::size_t>(nn);
  w.value<std::size_t>(nn ? 1 : 0);
  w.value<std::size_t>(nn);
  w.endLine();
  for (int dim = 0; dim < 4; ++dim)
    for (size_t e = 0; e < byEntity[dim].size(); ++e) {
      const std::vector<int>& list = byEntity[dim][e];
      if (list.empty()) continue;
      w.value<int>(dim);
      w.value<int>(static_cast<int>(e) + 1);
      w.value<int>(0);
      w.value<std::size_t>(list.size());
      w.endLine();
      for (int n : list) {
        w.value<std::size_t>(static_cast<std::size_t>(n) + 1);
        w.endLine();
      }
      for (int n : list) {
        for (int k = 0; k < 3; ++k) w.value<double>(m.nodes()[n][k]);
        w.endLine();
      }
    }
  w.endSection("$EndNodes");
}

void writeElements(const OutputMesh& m, MshOut& w) {
  struct Block {
    Shape shape;
    int dim, entity;
    const std::vector<int>* elements;
  };
  const auto tris = m.byEntity(Shape::Triangle), quads = m.byEntity(Shape::Quad), tets = m.byEntity(Shape::Tet);
  std::vector<Block> blocks;
  for (size_t f = 0; f < tris.size(); ++f) {
    if (!tris[f].empty()) blocks.push_back({Shape::Triangle, 2, static_cast<int>(f), &tris[f]});
    if (!quads[f].empty()) blocks.push_back({Shape::Quad, 2, static_cast<int>(f), &quads[f]});
  }
  for (size_t s = 0; s < tets.size(); ++s)
    if (!tets[s].empty()) blocks.push_back({Shape::Tet, 3, static_cast<int>(s), &tets[s]});
  const std::size_t ne = static_cast<std::size_t>(m.count(Shape::Triangle) + m.count(Shape::Quad) + m.count(Shape::Tet));
  w.text("$Elements\n");
  w.value<std::size_t>(blocks.size());
  w.value<std::size_t>(ne);
  w.value<std::size_t>(ne ? 1 : 0);
  w.value<std::size_t>(ne);
  w.endLine();
  std::size_t tag = 1;
  std::array<int, 10> nodes{};
  for (const Block& b : blocks) {
    const bool q = m.quadratic(b.shape);
    const auto& perm = b.shape == Shape::Tet && q ? order::kGmshTet10 : order::kIdentity;
    w.value<int>(b.dim);
    w.value<int>(b.entity + 1);
    w.value<int>(gmshElementType(b.shape, q));
    w.value<std::size_t>(b.elements->size());
    w.endLine();
    if (b.shape == Shape::Tet && !q) {  // the bulk of a volume mesh: the corners directly
      for (int e : *b.elements) {
        w.value<std::size_t>(tag++);
        for (const int v : m.volume->tets[e]) w.value<std::size_t>(static_cast<std::size_t>(v) + 1);
        w.endLine();
      }
      continue;
    }
    for (int e : *b.elements) {
      const int k = m.elementNodes(b.shape, e, nodes);
      w.value<std::size_t>(tag++);
      for (int j = 0; j < k; ++j) w.value<std::size_t>(static_cast<std::size_t>(nodes[perm[j]]) + 1);
      w.endLine();
    }
  }
  w.endSection("$EndElements");
}

}  // namespace

void writeMsh41(const OutputMesh& m, const std::string& path, const WriteOptions& opt) {
  const auto byEntity = nodesByEntity(m);
  AtomicFile file(path, opt.binary);
  std::ostream& o = file.stream();
  MshOut w(o, opt.binary);
  writeMshHeader(o, "4.1", opt.binary, m);
  writeEntities(m, w, byEntity);
  writeNodes(m, w, byEntity);
  writeElements(m, w);
  for (const NodeData& d : opt.nodeData) writeMshNodeData(w, d);
  file.commit();
}

}  // namespace aniso::io
