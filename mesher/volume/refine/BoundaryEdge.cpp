#include "mesher/volume/refine/BoundaryEdge.h"

namespace aniso::refine3d {

bool isBoundaryEdge(const SolidTetMesh& s, del3d::TetId t, int i, int j) {
  const del3d::TetMesh& mesh = s.mesh;
  const del3d::VertexId a = mesh.vertex(t, i), b = mesh.vertex(t, j);
  if (!s.isFixed(a) || !s.isFixed(b)) return false;
  // Rotate around (a, b) from t: across the face opposite x, where (x, y) are the two
  // other vertices; the edge is on the hull iff some step has no neighbour.
  int x = -1, y = -1;
  for (int m = 0; m < 4; ++m)
    if (m != i && m != j) (x < 0 ? x : y) = m;
  del3d::TetId cur = t;
  del3d::VertexId vx = mesh.vertex(t, x), vy = mesh.vertex(t, y);
  for (std::size_t guard = 0; guard < (std::size_t{1} << 20); ++guard) {
    const int ix = mesh.localIndex(cur, vx);
    if (mesh.isConstrained(cur, ix)) return true;
    const del3d::TetId n = mesh.neighbour(cur, ix);
    if (!n.valid()) return true;
    if (n == t) return false;
    // in n, the vertex other than a, b, vy
    del3d::VertexId z;
    for (int m = 0; m < 4; ++m) {
      const del3d::VertexId w = mesh.vertex(n, m);
      if (w != a && w != b && w != vy) z = w;
    }
    vx = vy;
    vy = z;
    cur = n;
  }
  return true;
}

}  // namespace aniso::refine3d
