#include "mesher/quad/OddSplit.h"

#include <array>

namespace aniso::quad {

OddSplitResult splitAndMerge(QuadMesh2d& mesh, VertexMetrics& metrics, int t1, int j, double minQuality) {
  OddSplitResult r;
  const int t2 = mesh.adj[t1][j];
  if (t2 == kNone || !mesh.isTriangle(t2)) return r;
  const Corners& c1 = mesh.corners[t1];
  const int u = c1[j], v = c1[(j + 1) % 3], x = c1[(j + 2) % 3];
  const int i = mesh.edgeIndex(t2, v, u);
  if (i == kNone) return r;
  const int d = mesh.corners[t2][(i + 2) % 3];
  const Vec2 centroid = (mesh.uv[u] + mesh.uv[v] + mesh.uv[d]) / 3.0;
  const int p = mesh.addVertex(centroid);
  const Corners quad{u, p, v, x};
  const std::array<Corners, 2> parts{Corners{u, d, p, kNone}, Corners{d, v, p, kNone}};
  bool legal = elementQuality(mesh, metrics, quad) >= minQuality;
  for (const Corners& t : parts) legal = legal && convexCCW(mesh, t);
  if (!legal) {
    mesh.removeLastVertex();
    metrics.invalidate(p);
    return r;
  }
  const std::array<int, 2> removed{t1, t2};
  const std::array<Corners, 3> added{quad, parts[0], parts[1]};
  const std::vector<int> ids = mesh.replacePatch(removed, added);
  r.done = true;
  r.quad = ids[0];
  return r;
}

OddSplitResult splitEdgeAndMerge(QuadMesh2d& mesh, VertexMetrics& metrics, int t1, int base, int j,
                                 double minQuality) {
  OddSplitResult r;
  const int t2 = mesh.adj[t1][j];
  if (t2 == kNone || !mesh.isTriangle(t2) || base == j) return r;
  const Corners& c1 = mesh.corners[t1];
  const int u = c1[j], v = c1[(j + 1) % 3], x = c1[(j + 2) % 3];
  const int i = mesh.edgeIndex(t2, v, u);
  if (i == kNone) return r;
  const int d = mesh.corners[t2][(i + 2) % 3];
  const int m = mesh.addVertex(0.5 * (mesh.uv[u] + mesh.uv[v]));
  // The base edge is (x, u) (edge j+2) or (v, x) (edge j+1).
  const bool baseAtU = base == (j + 2) % 3;
  const Corners quad = baseAtU ? Corners{u, d, m, x} : Corners{m, d, v, x};
  const Corners rest1 = baseAtU ? Corners{m, v, x, kNone} : Corners{u, m, x, kNone};
  const Corners rest2 = baseAtU ? Corners{v, m, d, kNone} : Corners{m, u, d, kNone};
  const bool legal = elementQuality(mesh, metrics, quad) >= minQuality && convexCCW(mesh, rest1) &&
                     convexCCW(mesh, rest2);
  if (!legal) {
    mesh.removeLastVertex();
    metrics.invalidate(m);
    return r;
  }
  const std::array<int, 2> removed{t1, t2};
  const std::array<Corners, 3> added{quad, rest1, rest2};
  r.done = true;
  r.quad = mesh.replacePatch(removed, added)[0];
  return r;
}

}  // namespace aniso::quad
