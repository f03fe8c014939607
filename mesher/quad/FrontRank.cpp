#include "mesher/quad/FrontRank.h"

#include <algorithm>
#include <cmath>

namespace aniso::quad {
namespace {

/// The metric angle of element e at its corner i.
double cornerAngle(const QuadMesh2d& mesh, VertexMetrics& metrics, int e, int i) {
  const Corners& c = mesh.corners[e];
  const int n = mesh.sides(e);
  const Mat2 s = metrics.element(c);
  const Vec2 p = mesh.uv[c[i]];
  const Vec2 x = s * (mesh.uv[c[(i + 1) % n]] - p), y = s * (mesh.uv[c[(i + n - 1) % n]] - p);
  return std::atan2(x.x() * y.y() - x.y() * y.x(), x.dot(y));
}

}  // namespace

bool isFrontEdge(const QuadMesh2d& mesh, int e, int k) {
  if (!mesh.isTriangle(e)) return false;
  const int f = mesh.adj[e][k];
  return f == kNone || mesh.isQuad(f);
}

double regionAngle(const QuadMesh2d& mesh, VertexMetrics& metrics, int v, int e, bool ccw) {
  double sum = 0;
  int f = e;
  for (int steps = 0; steps < 256; ++steps) {
    const int n = mesh.sides(f), i = mesh.cornerIndex(f, v);
    sum += cornerAngle(mesh, metrics, f, i);
    // Counter-clockwise around v: across the edge entering v; clockwise: the edge leaving it.
    const int g = mesh.adj[f][ccw ? (i + n - 1) % n : i];
    if (g == kNone || !mesh.isTriangle(g) || g == e) break;
    f = g;
  }
  return sum;
}

FrontEdgeClass classifyFrontEdge(const QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, int level,
                                 const FrontWeights& w) {
  FrontEdgeClass c;
  const int a = mesh.corners[e][k], b = mesh.corners[e][(k + 1) % 3];
  // At a the region lies counter-clockwise of the front edge a→b, at b clockwise of it.
  c.alphaL = regionAngle(mesh, metrics, a, e, true);
  c.alphaR = regionAngle(mesh, metrics, b, e, false);
  const int small = (c.alphaL < w.alpha1) + (c.alphaR < w.alpha1);
  c.a1 = small == 2 ? 0 : (small == 1 ? 1 : 2);
  c.a2 = (c.alphaL < w.alpha2 || c.alphaR < w.alpha2) ? 1 : 0;
  c.a3 = level;
  const double l2 = std::pow(metrics.length(a, b), 2);
  c.a4 = l2 > 2 ? static_cast<int>(std::floor(std::min(l2, 1e6))) : 0;
  c.a5 = static_cast<int>(std::floor(std::min(metrics.gradation(a, b), 1e6) - 1));
  c.rank = w.type * c.a1 + w.smallAngle * c.a2 + w.level * c.a3 + w.length * c.a4 + w.gradation * c.a5;
  return c;
}

}  // namespace aniso::quad
