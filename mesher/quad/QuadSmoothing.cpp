#include "mesher/quad/QuadSmoothing.h"

#include <algorithm>
#include <cmath>

namespace aniso::quad {

void VertexElements::build(const QuadMesh2d& mesh) {
  start.assign(mesh.numVertices() + 1, 0);
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int k = 0; k < mesh.sides(e); ++k) ++start[mesh.corners[e][k] + 1];
  for (int v = 0; v < mesh.numVertices(); ++v) start[v + 1] += start[v];
  elements.assign(start.back(), 0);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int k = 0; k < mesh.sides(e); ++k) elements[fill[mesh.corners[e][k]]++] = e;
}

StarQuality starQuality(const QuadMesh2d& mesh, VertexMetrics& metrics, std::span<const int> star) {
  StarQuality s;
  for (int e : star) {
    const double q = elementQuality(mesh, metrics, mesh.corners[e]);
    if (q <= 0) s.valid = false;
    s.worst = std::min(s.worst, q);
    if (mesh.sides(e) == 4) s.worstQuad = std::min(s.worstQuad, q);
    s.mean += q;
  }
  s.mean /= std::max<std::size_t>(1, star.size());
  return s;
}

std::vector<std::uint8_t> frozenVertices(const QuadMesh2d& mesh) {
  std::vector<std::uint8_t> frozen(mesh.boundary.begin(), mesh.boundary.end());
  for (int e = 0; e < mesh.numElements(); ++e) {
    const int n = mesh.sides(e);
    bool pole = false;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        const int a = mesh.node[mesh.corners[e][i]], b = mesh.node[mesh.corners[e][j]];
        pole = pole || (a >= 0 && a == b);
      }
    if (pole)
      for (int i = 0; i < n; ++i) frozen[mesh.corners[e][i]] = 1;
  }
  return frozen;
}

namespace {

Vec2 target(const QuadMesh2d& mesh, VertexMetrics& metrics, int v, std::span<const int> star) {
  const Mat2& sq = metrics.at(v);
  const double detQ = sq.determinant();
  Vec2 sum(0, 0);
  int n = 0;
  for (int e : star) {
    const int s = mesh.sides(e), k = mesh.cornerIndex(e, v);
    for (int nb : {mesh.corners[e][(k + 1) % s], mesh.corners[e][(k + s - 1) % s]}) {
      // Each edge neighbour appears in two elements around an inner vertex: counted twice,
      // evenly, so the mean is unchanged.
      Mat2 si = 0.5 * (sq + metrics.at(nb));
      const double d = si.determinant();
      if (d > 0 && detQ > 0) si *= std::sqrt(detQ / d);
      sum += si * (mesh.uv[nb] - mesh.uv[v]);
      ++n;
    }
  }
  if (n == 0 || !(std::abs(detQ) > 0)) return mesh.uv[v];
  return mesh.uv[v] + sq.inverse() * (sum / n);
}

}  // namespace

SmoothStats smoothQuadMesh(QuadMesh2d& mesh, VertexMetrics& metrics, const SmoothOptions& o) {
  SmoothStats st;
  VertexElements ve;
  ve.build(mesh);
  const std::vector<std::uint8_t> frozen = frozenVertices(mesh);
  for (int sweep = 0; sweep < o.sweeps; ++sweep) {
    std::vector<int> moved;
    for (int v = 0; v < mesh.numVertices(); ++v) {
      const std::span<const int> star = ve.of(v);
      if (frozen[v] || star.empty()) continue;
      const StarQuality before = starQuality(mesh, metrics, star);
      const Vec2 q = mesh.uv[v], t = target(mesh, metrics, v, star);
      if (!t.allFinite() || t == q) continue;
      bool accepted = false;
      for (double step : {1.0, 0.5}) {
        mesh.uv[v] = q + step * (t - q);
        metrics.refreshPoint(v);
        const StarQuality after = starQuality(mesh, metrics, star);
        const bool better = before.worst < o.qualityFloor ? after.worst > before.worst
                                                          : after.worst >= o.qualityFloor;
        // No quad may fall below the acceptance threshold (or below itself, if already there).
        const bool quadsKept = after.worstQuad >= std::min(before.worstQuad, o.minQuadQuality);
        if (after.valid && better && quadsKept) {
          accepted = true;
          break;
        }
      }
      if (accepted) {
        ++st.moved;
        moved.push_back(v);
      } else {
        mesh.uv[v] = q;
        metrics.refreshPoint(v);
        ++st.rejected;
      }
    }
    for (int v : moved) metrics.invalidate(v);
  }
  return st;
}

}  // namespace aniso::quad
