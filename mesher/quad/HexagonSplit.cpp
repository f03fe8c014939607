#include "mesher/quad/HexagonSplit.h"

#include <algorithm>
#include <array>
#include <vector>

#include "mesher/quad/PairSplit.h"

namespace aniso::quad {
namespace {

/// Candidate inner vertex of a quad (a, b, c, X) with a, b, c on the hexagon: X on the ray
/// from b through the midpoint m of a and c at m + τ (m − b) (τ = 1: the parallelogram
/// completion; small τ: a kite with the angle at b kept whole), moved the fraction μ
/// towards the hexagon's centroid.
constexpr std::array<double, 4> kBeyondMidpoint{0.1, 0.3, 0.6, 1.0};
constexpr std::array<double, 3> kTowardsCentroid{0.0, 0.3, 0.6};

std::vector<Vec2> candidates(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& centroid) {
  std::vector<Vec2> out;
  const Vec2 m = 0.5 * (a + c);
  for (double tau : kBeyondMidpoint)
    for (double mu : kTowardsCentroid) out.push_back((1 - mu) * (m + tau * (m - b)) + mu * centroid);
  return out;
}

using Hexagon = std::array<int, 6>;

struct Best {
  double worst = -2;
  std::array<Corners, 4> quads{};
  Vec2 x1{0, 0}, x2{0, 0};
};

/// The four quads of rotation r with inner vertices x1, x2 (vertex ids).
std::array<Corners, 4> quadsOf(const Hexagon& h, int r, int x1, int x2) {
  const auto at = [&](int i) { return h[(i + r) % 6]; };
  return {Corners{at(2), at(3), at(4), x1}, Corners{at(5), at(0), at(1), x2}, Corners{at(4), at(5), x2, x1},
          Corners{at(1), at(2), x1, x2}};
}

/// Tries every rotation and candidate position of the inner vertices x1, x2 (added by
/// the caller) on hexagon h; returns the best.
Best search(QuadMesh2d& mesh, VertexMetrics& metrics, const Hexagon& h, int x1, int x2) {
  Vec2 centroid(0, 0);
  for (int v : h) centroid += mesh.uv[v];
  centroid /= 6.0;
  Best best;
  for (int r = 0; r < 3; ++r) {
    const auto uv = [&](int i) { return mesh.uv[h[(i + r) % 6]]; };
    const std::vector<Vec2> c1 = candidates(uv(2), uv(3), uv(4), centroid);
    const std::vector<Vec2> c2 = candidates(uv(5), uv(0), uv(1), centroid);
    for (const Vec2& p1 : c1)
      for (const Vec2& p2 : c2) {
        mesh.uv[x1] = p1;
        mesh.uv[x2] = p2;
        metrics.invalidate(x1);
        metrics.invalidate(x2);
        const std::array<Corners, 4> quads = quadsOf(h, r, x1, x2);
        double worst = 2;
        for (const Corners& q : quads) worst = std::min(worst, elementQuality(mesh, metrics, q));
        if (worst > best.worst) best = {worst, quads, mesh.uv[x1], mesh.uv[x2]};
      }
  }
  return best;
}

}  // namespace

bool splitPairWithQuad(QuadMesh2d& mesh, VertexMetrics& metrics, int a, int b, double minQuality) {
  const std::optional<PairOutline> outline = pairOutline(mesh, a, b);
  if (!outline) return false;
  const std::array<int, 4>& p = outline->p;
  const std::array<int, 4>& outside = outline->outside;
  for (int j = 0; j < 4; ++j) {
    const int q = outside[j];
    if (q == kNone || !mesh.isQuad(q)) continue;
    const int s = mesh.edgeIndex(q, p[(j + 1) % 4], p[j]);
    if (s == kNone) continue;
    const int f = mesh.corners[q][(s + 2) % 4], g = mesh.corners[q][(s + 3) % 4];
    if (std::count(p.begin(), p.end(), f) || std::count(p.begin(), p.end(), g)) continue;
    const Hexagon h{p[j], f, g, p[(j + 1) % 4], p[(j + 2) % 4], p[(j + 3) % 4]};
    const int x1 = mesh.addVertex(Vec2::Zero()), x2 = mesh.addVertex(Vec2::Zero());
    const Best best = search(mesh, metrics, h, x1, x2);
    metrics.invalidate(x1);
    metrics.invalidate(x2);
    if (best.worst >= minQuality) {
      mesh.uv[x1] = best.x1;
      mesh.uv[x2] = best.x2;
      const std::array<int, 3> removed{a, b, q};
      mesh.replacePatch(removed, best.quads);
      return true;
    }
    mesh.removeLastVertex();
    mesh.removeLastVertex();
  }
  return false;
}

}  // namespace aniso::quad
