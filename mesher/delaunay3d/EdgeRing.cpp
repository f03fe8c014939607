#include "mesher/delaunay3d/EdgeRing.h"

#include "mesher/core/Error.h"

namespace aniso::del3d {
namespace {

constexpr std::size_t kMaxRing = 1000000;

// The vertex of tet n that is none of a, b, y.
VertexId fourth(const TetMesh& mesh, TetId n, VertexId a, VertexId b, VertexId y) {
  for (int m = 0; m < 4; ++m) {
    const VertexId w = mesh.vertex(n, m);
    if (w != a && w != b && w != y) return w;
  }
  throw MeshingError("edgeRing: neighbour does not contain the edge");
}

}  // namespace

void edgeRing(const TetMesh& mesh, TetId t, int i, int j, EdgeRing& ring) {
  ring.tets.clear();
  ring.apex.clear();
  ring.a = mesh.vertex(t, i);
  ring.b = mesh.vertex(t, j);
  const VertexId a = ring.a, b = ring.b;
  int k = 0;
  while (k == i || k == j) ++k;
  int l = 0;
  while (l == i || l == j || l == k) ++l;
  // State (tet, x, y): the tet holds a, b, x, y; moving forward crosses the face opposite x.
  // Backward first, crossing opposite y, to find the start of an open ring.
  TetId cur = t;
  VertexId x = mesh.vertex(t, k), y = mesh.vertex(t, l);
  ring.closed = false;
  for (std::size_t step = 0;; ++step) {
    if (step > kMaxRing) throw MeshingError("edgeRing: rotation does not close");
    const TetId n = mesh.neighbour(cur, mesh.localIndex(cur, y));
    if (!n.valid()) break;
    if (n == t) {
      ring.closed = true;
      break;
    }
    const VertexId w = fourth(mesh, n, a, b, x);
    cur = n;
    y = x;
    x = w;
  }
  if (ring.closed) {
    cur = t;
    x = mesh.vertex(t, k);
    y = mesh.vertex(t, l);
  }
  const TetId first = cur;
  for (std::size_t step = 0;; ++step) {
    if (step > kMaxRing) throw MeshingError("edgeRing: rotation does not close");
    ring.tets.push_back(cur);
    ring.apex.push_back(x);
    const TetId n = mesh.neighbour(cur, mesh.localIndex(cur, x));
    if (!n.valid()) {
      ring.apex.push_back(y);
      break;
    }
    if (n == first) break;
    const VertexId z = fourth(mesh, n, a, b, y);
    cur = n;
    x = y;
    y = z;
  }
}

int closedEdgeRing(const TetMesh& mesh, TetId t, int i, int j, std::span<TetId> tets,
                   std::span<VertexId> apex) {
  int k = 0;
  while (k == i || k == j) ++k;
  int l = 0;
  while (l == i || l == j || l == k) ++l;
  TetId cur = t;
  VertexId x = mesh.vertex(t, k), y = mesh.vertex(t, l);
  for (std::size_t n = 0; n < tets.size(); ++n) {
    tets[n] = cur;
    apex[n] = x;
    const std::uint32_t code = mesh.adjacentCode(cur, mesh.localIndex(cur, x));
    const TetId next = codeTet(code);
    if (!next.valid()) return -1;
    if (next == t) return static_cast<int>(n + 1);
    // The vertex of next opposite the shared face (a, b, y): none of a, b, y.
    const VertexId z = mesh.vertex(next, codeFace(code));
    cur = next;
    x = y;
    y = z;
  }
  return -1;
}

}  // namespace aniso::del3d
