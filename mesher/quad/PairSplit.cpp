#include "mesher/quad/PairSplit.h"

#include <algorithm>
#include <array>

namespace aniso::quad {

std::optional<PairOutline> pairOutline(const QuadMesh2d& mesh, int a, int b) {
  if (!mesh.isTriangle(a) || !mesh.isTriangle(b)) return std::nullopt;
  int k = kNone;
  for (int x = 0; x < 3; ++x)
    if (mesh.adj[a][x] == b) k = x;
  if (k == kNone) return std::nullopt;
  const Corners& c = mesh.corners[a];
  const int u = c[k], v = c[(k + 1) % 3], w = c[(k + 2) % 3];
  const int i = mesh.edgeIndex(b, v, u);
  if (i == kNone) return std::nullopt;
  return PairOutline{{u, mesh.corners[b][(i + 2) % 3], v, w},
                     {mesh.adj[b][(i + 1) % 3], mesh.adj[b][(i + 2) % 3], mesh.adj[a][(k + 1) % 3], mesh.adj[a][(k + 2) % 3]}};
}

bool splitPairIntoQuads(QuadMesh2d& mesh, VertexMetrics& metrics, int a, int b, double minQuality) {
  const std::optional<PairOutline> outline = pairOutline(mesh, a, b);
  if (!outline) return false;
  const std::array<int, 4>& p = outline->p;
  const int u = p[0], v = p[2];
  const Vec2 centre = 0.5 * (mesh.uv[u] + mesh.uv[v]);
  // Metric lengths of the rays from the centre to the corners (star-shaped: inside).
  const Mat2 s = 0.5 * (metrics.at(u) + metrics.at(v));
  std::array<double, 4> len{};
  double shortest = 1e300;
  for (int j = 0; j < 4; ++j) {
    len[j] = (s * (mesh.uv[p[j]] - centre)).norm();
    shortest = std::min(shortest, len[j]);
  }
  if (!(shortest > 0)) return false;
  for (double lambda : {0.5, 0.35, 0.7}) {
    std::array<int, 4> g{};
    for (int j = 0; j < 4; ++j)
      g[j] = mesh.addVertex(centre + (lambda * shortest / len[j]) * (mesh.uv[p[j]] - centre));
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
