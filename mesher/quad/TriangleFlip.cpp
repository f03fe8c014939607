#include "mesher/quad/TriangleFlip.h"

#include <array>

#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

int flipTriangleEdge(QuadMesh2d& mesh, int f, int k) {
  const int g = mesh.adj[f][k];
  if (g == kNone || !mesh.isTriangle(g)) return kNone;
  const int x = mesh.corners[f][k], y = mesh.corners[f][(k + 1) % 3], p = mesh.corners[f][(k + 2) % 3];
  const int j = mesh.edgeIndex(g, y, x);
  if (j == kNone) return kNone;
  const int w = mesh.corners[g][(j + 2) % 3];
  const std::array<Corners, 2> added{Corners{p, x, w, kNone}, Corners{p, w, y, kNone}};
  if (!convexCCW(mesh, added[0]) || !convexCCW(mesh, added[1])) return kNone;
  const std::array<int, 2> removed{f, g};
  mesh.replacePatch(removed, added);
  return w;
}

}  // namespace aniso::quad
