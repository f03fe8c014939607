#include "mesher/volume/CarveSolid.h"

#include <algorithm>

#include "mesher/delaunay3d/RemoveTets.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/volume/MeshQueries.h"

namespace aniso {

using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

std::vector<std::string> carveSolid(SolidTetMesh& s, const SolidBoundary& boundary, const del3d::EnclosingBox& box) {
  TetMesh& m = s.mesh;
  const std::string solid = "solid " + std::to_string(s.solid + 1);
  std::vector<std::string> problems;
  std::vector<TetId> star;
  // (tet, face) -> boundary triangle, on both tets of the face.
  std::vector<int> faceTriangle(4 * static_cast<std::size_t>(m.tetSlots()), -1);
  for (std::size_t t = 0; t < boundary.triangles.size(); ++t) {
    const auto& tri = boundary.triangles[t];
    const volume::FaceHandle h = volume::findFace(m, tri[0], tri[1], tri[2], star);
    if (!h.valid()) {
      problems.push_back(solid + ": boundary triangle on face " + std::to_string(boundary.triangleFace[t] + 1) +
                         " is not a face of the tetrahedra");
      continue;
    }
    if (!m.isConstrained(h.tet, h.face)) m.setConstrained(h.tet, h.face, true);
    faceTriangle[4 * static_cast<std::size_t>(h.tet.index) + h.face] = static_cast<int>(t);
    if (const TetId n = m.neighbour(h.tet, h.face); n.valid())
      for (int j = 0; j < 4; ++j)
        if (m.neighbour(n, j) == h.tet) faceTriangle[4 * static_cast<std::size_t>(n.index) + j] = static_cast<int>(t);
  }
  if (!problems.empty()) return problems;
  // Components across non-constrained faces (and embedded ones).
  std::vector<int> comp(m.tetSlots(), -1);
  std::vector<int> verdict;  // per component: 1 inside, 0 outside, -1 unknown
  std::vector<TetId> queue;
  long long conflicts = 0, strayConstraints = 0;
  for (std::uint32_t k = 0; k < m.tetSlots(); ++k) {
    if (!m.isAlive(TetId(k)) || comp[k] >= 0) continue;
    const int c = static_cast<int>(verdict.size());
    verdict.push_back(-1);
    bool outside = false;
    queue.assign(1, TetId(k));
    comp[k] = c;
    for (std::size_t q = 0; q < queue.size(); ++q) {
      const TetId t = queue[q];
      for (int m4 = 0; m4 < 4; ++m4)
        if (m.vertex(t, m4).index < 8 && std::find(box.corners.begin(), box.corners.end(), m.vertex(t, m4)) != box.corners.end())
          outside = true;
      for (int i = 0; i < 4; ++i) {
        const TetId n = m.neighbour(t, i);
        if (!n.valid()) {
          outside = true;
          continue;
        }
        int triangle = -1;
        if (m.isConstrained(t, i)) {
          triangle = faceTriangle[4 * static_cast<std::size_t>(t.index) + i];
          if (triangle < 0) {
            ++strayConstraints;
            continue;
          }
        }
        // Across a free face, and across an embedded one (the solid on both sides).
        if (triangle < 0 || boundary.isEmbedded(static_cast<std::size_t>(triangle))) {
          if (comp[n.index] < 0) {
            comp[n.index] = c;
            queue.push_back(n);
          }
          continue;
        }
        const auto& tri = boundary.triangles[static_cast<std::size_t>(triangle)];
        const double o = predicates::orient3d(m.coords(tri[0]), m.coords(tri[1]), m.coords(tri[2]), m.coords(m.vertex(t, i)));
        const int v = o < 0 ? 1 : 0;
        if (verdict[c] < 0) verdict[c] = v;
        else if (verdict[c] != v) ++conflicts;
      }
    }
    if (outside) {
      if (verdict[c] == 1) ++conflicts;
      verdict[c] = 0;
    }
  }
  if (strayConstraints)
    problems.push_back(solid + ": " + std::to_string(strayConstraints) + " constrained faces are not boundary triangles");
  if (conflicts)
    problems.push_back(solid + ": inside/outside classification disagrees at " + std::to_string(conflicts) +
                       " boundary faces (missing or misoriented boundary)");
  if (!problems.empty()) return problems;
  std::vector<TetId> remove;
  for (std::uint32_t k = 0; k < m.tetSlots(); ++k)
    if (m.isAlive(TetId(k)) && verdict[comp[k]] != 1) remove.push_back(TetId(k));
  del3d::removeTets(m, remove);
  // Constrained faces now on the hull keep their bit on the inside tet (removeTets keeps it).
  return problems;
}

}  // namespace aniso
