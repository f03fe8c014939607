#include "mesher/quad/PairSplit.h"

#include <array>

namespace aniso::quad {

bool splitPairIntoQuads(QuadMesh2d& mesh, VertexMetrics& metrics, int a, int b, double minQuality) {
  if (!mesh.isTriangle(a) || !mesh.isTriangle(b)) return false;
  int k = kNone;
  for (int x = 0; x < 3; ++x)
    if (mesh.adj[a][x] == b) k = x;
  if (k == kNone) return false;
  const Corners& c = mesh.corners[a];
  const int u = c[k], v = c[(k + 1) % 3], x = c[(k + 2) % 3];
  const int i = mesh.edgeIndex(b, v, u);
  if (i == kNone) return false;
  const std::array<int, 4> p{u, mesh.corners[b][(i + 2) % 3], v, x};
  const Vec2 centre = 0.5 * (mesh.uv[u] + mesh.uv[v]);
  for (double lambda : {0.5, 0.35, 0.65}) {
    std::array<int, 4> g{};
    for (int j = 0; j < 4; ++j) g[j] = mesh.addVertex(mesh.uv[p[j]] + lambda * (centre - mesh.uv[p[j]]));
    std::array<Corners, 5> quads{Corners{g[0], g[1], g[2], g[3]}};
    for (int j = 0; j < 4; ++j) quads[j + 1] = {p[j], p[(j + 1) % 4], g[(j + 1) % 4], g[j]};
    bool legal = true;
    for (const Corners& q : quads) legal = legal && elementQuality(mesh, metrics, q) >= minQuality;
    if (legal) {
      const std::array<int, 2> removed{a, b};
      mesh.replacePatch(removed, quads);
      return true;
    }
    for (int j = 3; j >= 0; --j) {
      mesh.removeLastVertex();
      metrics.invalidate(g[j]);
    }
  }
  return false;
}

}  // namespace aniso::quad
