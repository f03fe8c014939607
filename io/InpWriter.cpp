// Abaqus / CalculiX INP writer (keywords as the CalculiX User's Manual describes them:
// *NODE, *ELEMENT, *NSET, *ELSET, *SURFACE). Data lines hold at most 16 entries.
#include <algorithm>
#include <cstdio>
#include <ostream>
#include <unordered_map>
#include <vector>

#include "io/AtomicFile.h"
#include "io/ElementOrder.h"
#include "io/FormatWriters.h"

namespace aniso::io {
namespace {

/// Writes ids 16 per line, comma separated.
void writeIdList(std::ostream& o, const std::vector<long long>& ids) {
  for (size_t i = 0; i < ids.size(); ++i) {
    o << ids[i] << ((i + 1) % 16 == 0 || i + 1 == ids.size() ? "\n" : ", ");
  }
}

void writeNodes(std::ostream& o, const std::vector<Vec3>& p) {
  o << "*NODE, NSET=NALL\n";
  char buf[128];
  for (size_t i = 0; i < p.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%zu, %.17g, %.17g, %.17g\n", i + 1, p[i].x(), p[i].y(), p[i].z());
    o << buf;
  }
}

/// One *ELEMENT block; `ids` receives the element numbers given, starting at `next`.
void writeElementBlock(std::ostream& o, const OutputMesh& m, Shape s, const std::vector<int>& elements,
                       const char* type, const std::string& elset, long long& next, std::vector<long long>& ids) {
  if (elements.empty()) return;
  o << "*ELEMENT, TYPE=" << type;
  if (!elset.empty()) o << ", ELSET=" << elset;
  o << '\n';
  std::array<int, 10> nodes{};
  for (int e : elements) {
    const int k = m.elementNodes(s, e, nodes);  // Abaqus order is our canonical order
    ids[e] = next;
    o << next++;
    for (int j = 0; j < k; ++j) o << ", " << nodes[j] + 1;
    o << '\n';
  }
}

/// The nodes (1-based, ascending, each once) of every face's triangles and quads.
std::vector<std::vector<long long>> faceNodeIds(const OutputMesh& m) {
  std::vector<std::vector<long long>> faceNodes(m.model.faces.size());
  std::array<int, 10> nodes{};
  for (Shape s : {Shape::Triangle, Shape::Quad})
    for (int i = 0, n = m.count(s); i < n; ++i) {
      const int k = m.elementNodes(s, i, nodes);
      for (int j = 0; j < k; ++j) faceNodes[m.entityOf(s, i)].push_back(nodes[j] + 1);
    }
  for (std::vector<long long>& ids : faceNodes) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  }
  return faceNodes;
}

/// *NSET FACE<n> for every meshed face: the nodes of its triangles and quads.
void writeFaceNodeSets(std::ostream& o, const std::vector<std::vector<long long>>& faceNodes) {
  for (size_t f = 0; f < faceNodes.size(); ++f) {
    if (faceNodes[f].empty()) continue;
    o << "*NSET, NSET=FACE" << f + 1 << '\n';
    writeIdList(o, faceNodes[f]);
  }
}

/// Per named face group (groupNames), after everything else: *NSET <name> of its faces'
/// nodes and the union of its faces' `perFace` lists written by `write` (nothing when
/// they are all empty).
template <class T, class Write>
void writeFaceGroups(std::ostream& o, const OutputMesh& m, const std::vector<std::vector<long long>>& faceNodes,
                     const std::vector<std::vector<T>>& perFace, const Write& write) {
  for (const FaceGroup& g : groupNames(m.model).faces) {
    const std::vector<long long> nodes = groupIds(g, faceNodes);
    if (nodes.empty()) continue;
    std::vector<T> items;
    for (const int f : g.faces) items.insert(items.end(), perFace[f].begin(), perFace[f].end());
    o << "*NSET, NSET=" << g.name << '\n';
    writeIdList(o, nodes);
    if (!items.empty()) write(g.name, items);
  }
}

/// *NSET EDGE<n> for every model edge with nodes: the nodes on its curve and at its two
/// vertices (a shell's edge clamped by name: *BOUNDARY, EDGE3, 1, 6). An edge that took
/// its coincident twin's nodes (surface/contour/CoincidentEdges.h) has only its vertices.
void writeEdgeNodeSets(std::ostream& o, const OutputMesh& m) {
  const std::size_t nEdges = m.model.edges.size();
  std::vector<std::vector<long long>> edgeNodes(nEdges), vertexNodes(m.model.vertices.size());
  const std::vector<NodeOn>& on = m.surface.nodeOn;
  for (std::size_t i = 0; i < on.size() && i < m.nodes().size(); ++i) {
    const auto id = static_cast<long long>(i) + 1;
    if (on[i].kind == NodeOn::Kind::Edge && on[i].entity >= 0 && static_cast<std::size_t>(on[i].entity) < nEdges)
      edgeNodes[static_cast<std::size_t>(on[i].entity)].push_back(id);
    else if (on[i].kind == NodeOn::Kind::Vertex && on[i].entity >= 0 &&
             static_cast<std::size_t>(on[i].entity) < vertexNodes.size())
      vertexNodes[static_cast<std::size_t>(on[i].entity)].push_back(id);
  }
  for (std::size_t e = 0; e < nEdges; ++e) {
    const ModelEdge& me = m.model.edges[e];
    if (me.degenerate) continue;
    std::vector<long long>& ids = edgeNodes[e];
    for (const int v : {me.v0, me.v1})
      if (v >= 0 && static_cast<std::size_t>(v) < vertexNodes.size())
        ids.insert(ids.end(), vertexNodes[static_cast<std::size_t>(v)].begin(), vertexNodes[static_cast<std::size_t>(v)].end());
    if (ids.size() < 2) continue;
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    o << "*NSET, NSET=EDGE" << e + 1 << '\n';
    writeIdList(o, ids);
  }
}

struct TripleHash {
  std::size_t operator()(const std::array<int, 3>& t) const {
    std::size_t h = static_cast<std::size_t>(t[0]);
    h = h * 1000003u ^ static_cast<std::size_t>(t[1]);
    return h * 1000003u ^ static_cast<std::size_t>(t[2]);
  }
};

std::array<int, 3> sorted(int a, int b, int c) {
  std::array<int, 3> t{a, b, c};
  std::sort(t.begin(), t.end());
  return t;
}

/// The tetrahedron faces (element, S1..S4) on every boundary triangle of each face; on a
/// face between two solids, the faces of the tetrahedra on both sides.
std::vector<std::vector<std::pair<long long, int>>> faceSides(const OutputMesh& m, const std::vector<long long>& tetIds) {
  const SurfaceMesh& sm = m.surface;
  std::unordered_map<std::array<int, 3>, int, TripleHash> triangleOf;
  triangleOf.reserve(sm.triangles.size() * 2);
  for (size_t t = 0; t < sm.triangles.size(); ++t) {
    const auto& tri = sm.triangles[t];
    triangleOf.emplace(sorted(tri[0], tri[1], tri[2]), static_cast<int>(t));
  }
  std::vector<std::vector<std::pair<long long, int>>> sides(sm.triangles.size());
  const auto& tets = m.volume->tets;
  for (size_t e = 0; e < tets.size(); ++e)
    for (int k = 0; k < 4; ++k) {
      const int* f = order::kAbaqusTetFaces[k];
      const auto it = triangleOf.find(sorted(tets[e][f[0]], tets[e][f[1]], tets[e][f[2]]));
      if (it != triangleOf.end()) sides[it->second].push_back({tetIds[e], k + 1});
    }
  std::vector<std::vector<int>> faceTris = m.byEntity(Shape::Triangle);
  std::vector<std::vector<std::pair<long long, int>>> out(faceTris.size());
  for (size_t f = 0; f < faceTris.size(); ++f)
    for (int t : faceTris[f]) out[f].insert(out[f].end(), sides[t].begin(), sides[t].end());
  return out;
}

/// *SURFACE <name>, TYPE=ELEMENT of element faces.
void writeSurface(std::ostream& o, const std::string& name, const std::vector<std::pair<long long, int>>& entries) {
  o << "*SURFACE, NAME=" << name << ", TYPE=ELEMENT\n";
  for (const auto& [id, k] : entries) o << id << ", S" << k << '\n';
}

}  // namespace

void writeInp(const OutputMesh& m, const std::string& path) {
  AtomicFile file(path);
  std::ostream& o = file.stream();
  o << "** anisomesh mesh: " << m.nodes().size() << " nodes\n";
  writeNodes(o, m.nodes());
  long long next = 1;
  if (m.isVolume()) {
    // Volume mesh: only 3D elements, one block and element set per solid.
    const std::vector<std::string> names = groupNames(m.model).solids;
    const auto tets = m.byEntity(Shape::Tet);
    std::vector<long long> tetIds(static_cast<size_t>(m.count(Shape::Tet)), 0);
    const char* type = m.quadratic(Shape::Tet) ? "C3D10" : "C3D4";
    for (size_t s = 0; s < tets.size(); ++s) writeElementBlock(o, m, Shape::Tet, tets[s], type, names[s], next, tetIds);
    if (next > 1) o << "*ELSET, ELSET=EALL, GENERATE\n1, " << next - 1 << ", 1\n";
    const auto faceNodes = faceNodeIds(m);
    writeFaceNodeSets(o, faceNodes);
    writeEdgeNodeSets(o, m);
    const auto sides = faceSides(m, tetIds);
    for (size_t f = 0; f < sides.size(); ++f)
      if (!sides[f].empty()) writeSurface(o, "S_FACE" + std::to_string(f + 1), sides[f]);
    writeFaceGroups(o, m, faceNodes, sides, [&o](const std::string& name, const auto& entries) {
      writeSurface(o, "S_" + name, entries);
    });
  } else {
    // Surface mesh: shell elements, an element set per face.
    std::vector<long long> triIds(static_cast<size_t>(m.count(Shape::Triangle)), 0);
    std::vector<long long> quadIds(static_cast<size_t>(m.count(Shape::Quad)), 0);
    std::vector<int> all;
    for (int i = 0; i < m.count(Shape::Triangle); ++i) all.push_back(i);
    writeElementBlock(o, m, Shape::Triangle, all, m.quadratic(Shape::Triangle) ? "S6" : "S3", "", next, triIds);
    all.clear();
    for (int i = 0; i < m.count(Shape::Quad); ++i) all.push_back(i);
    writeElementBlock(o, m, Shape::Quad, all, m.quadratic(Shape::Quad) ? "S8" : "S4", "", next, quadIds);
    const auto tris = m.byEntity(Shape::Triangle), quads = m.byEntity(Shape::Quad);
    std::vector<std::vector<long long>> faceElements(tris.size());
    for (size_t f = 0; f < tris.size(); ++f) {
      std::vector<long long>& ids = faceElements[f];
      for (int t : tris[f]) ids.push_back(triIds[t]);
      for (int q : quads[f]) ids.push_back(quadIds[q]);
      if (ids.empty()) continue;
      o << "*ELSET, ELSET=FACE" << f + 1 << '\n';
      writeIdList(o, ids);
    }
    if (next > 1) o << "*ELSET, ELSET=EALL, GENERATE\n1, " << next - 1 << ", 1\n";
    const auto faceNodes = faceNodeIds(m);
    writeFaceNodeSets(o, faceNodes);
    writeEdgeNodeSets(o, m);
    writeFaceGroups(o, m, faceNodes, faceElements, [&o](const std::string& name, std::vector<long long> ids) {
      std::sort(ids.begin(), ids.end());
      o << "*ELSET, ELSET=" << name << '\n';
      writeIdList(o, ids);
    });
  }
  file.commit();
}

}  // namespace aniso::io
