#include "mesher/volume/SolidTetMesh.h"

#include <algorithm>
#include <map>
#include <unordered_map>

#include "mesher/delaunay3d/Validate.h"

namespace aniso {

using del3d::TetId;
using del3d::VertexId;

std::vector<std::string> validateSolidTetMesh(const SolidTetMesh& s,
                                              const std::vector<std::array<int, 3>>& boundaryTriangles,
                                              const std::vector<std::array<int, 3>>& embeddedTriangles) {
  const del3d::TetMesh& m = s.mesh;
  std::vector<std::string> problems = del3d::validate(m);
  const std::string solid = "solid " + std::to_string(s.solid + 1) + ": ";
  if (s.node.size() != m.numVertices()) {
    problems.push_back(solid + "node map has " + std::to_string(s.node.size()) + " entries for " +
                       std::to_string(m.numVertices()) + " vertices");
    return problems;
  }
  std::unordered_map<int, std::uint32_t> vertexOfNode;
  for (std::uint32_t v = 0; v < s.node.size(); ++v)
    if (s.node[v] >= 0 && !vertexOfNode.emplace(s.node[v], v).second)
      problems.push_back(solid + "surface node " + std::to_string(s.node[v]) + " has two kernel vertices");
  // Hull faces and constrained faces, by sorted kernel triple.
  using Key = std::array<std::uint32_t, 3>;
  std::map<Key, int> hull, constrained;
  for (std::uint32_t k = 0; k < m.tetSlots(); ++k) {
    const TetId t(k);
    if (!m.isAlive(t)) continue;
    for (int i = 0; i < 4; ++i) {
      const bool onHull = !m.neighbour(t, i).valid();
      if (!onHull && !m.isConstrained(t, i)) continue;
      Key key;
      for (int j = 0; j < 3; ++j) key[j] = m.vertex(t, del3d::kFaceVertex[i][j]).index;
      std::sort(key.begin(), key.end());
      if (onHull) ++hull[key];
      if (m.isConstrained(t, i)) ++constrained[key];
    }
  }
  long long missing = 0, notConstrained = 0, notHull = 0, onHull = 0;
  std::map<Key, int> expected;  // boundary and embedded triangles
  const auto keyOf = [&](const std::array<int, 3>& tri, Key& key) {
    for (int j = 0; j < 3; ++j) {
      const auto it = vertexOfNode.find(tri[j]);
      if (it == vertexOfNode.end()) return false;
      key[j] = it->second;
    }
    std::sort(key.begin(), key.end());
    return true;
  };
  for (const auto& tri : boundaryTriangles) {
    Key key;
    if (!keyOf(tri, key)) {
      ++missing;
      continue;
    }
    ++expected[key];
    if (!hull.count(key)) ++notHull;
    if (!constrained.count(key)) ++notConstrained;
  }
  for (const auto& key : s.patchFaces) {  // hull faces closing the holes (CarveAroundHoles.h)
    ++expected[key];
    if (!hull.count(key)) ++notHull;
    if (!constrained.count(key)) ++notConstrained;
  }
  for (const auto& tri : embeddedTriangles) {  // constrained in both of its tets
    Key key;
    if (!keyOf(tri, key)) {
      ++missing;
      continue;
    }
    ++expected[key];
    if (hull.count(key)) ++onHull;
    const auto it = constrained.find(key);
    if (it == constrained.end() || it->second != 2) ++notConstrained;
  }
  if (missing) problems.push_back(solid + std::to_string(missing) + " boundary triangles have nodes not in the mesh");
  if (notHull) problems.push_back(solid + std::to_string(notHull) + " boundary triangles are not faces of exactly one tet");
  if (notConstrained) problems.push_back(solid + std::to_string(notConstrained) + " boundary triangles not constrained");
  if (onHull) problems.push_back(solid + std::to_string(onHull) + " embedded triangles are on the hull");
  long long strayHull = 0, strayConstrained = 0;
  for (const auto& [key, n] : hull)
    if (!expected.count(key) || n != 1) ++strayHull;
  for (const auto& [key, n] : constrained)
    if (!expected.count(key)) ++strayConstrained;
  if (strayHull) problems.push_back(solid + std::to_string(strayHull) + " hull faces are not boundary triangles");
  if (strayConstrained)
    problems.push_back(solid + std::to_string(strayConstrained) + " constrained faces are not boundary triangles");
  for (std::uint32_t v = 0; v < 8 && v < m.numVertices(); ++v)
    if (s.node[v] >= 0 || m.vertexTet(VertexId(v)).valid())
      problems.push_back(solid + "enclosing-box corner " + std::to_string(v) + " is a node or in a tet");
  return problems;
}

}  // namespace aniso
