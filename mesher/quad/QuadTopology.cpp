#include "mesher/quad/QuadTopology.h"

#include <array>
#include <cmath>
#include <numbers>

#include "mesher/quad/DiagonalCollapse.h"
#include "mesher/quad/QuadSmoothing.h"

namespace aniso::quad {
namespace {

class Topology {
 public:
  Topology(QuadMesh2d& mesh, VertexMetrics& metrics, const TopologyOptions& o)
      : mesh_(mesh), metrics_(metrics), o_(o) {}

  TopologyStats run() {
    for (int sweep = 0; sweep < o_.sweeps; ++sweep) {
      const TopologyStats before = st_;
      removeDoublets();
      st_.collapses += collapseDiagonals(mesh_, metrics_, o_.minQuality);
      countValences();
      const int n = mesh_.numElements();
      for (int e = 0; e < n; ++e)
        for (int k = 0; k < 4 && mesh_.isQuad(e); ++k) trySwap(e, k);
      if (st_.doublets == before.doublets && st_.swaps == before.swaps && st_.collapses == before.collapses) break;
    }
    return st_;
  }

 private:
  void removeDoublets() {
    VertexElements ve;
    ve.build(mesh_);
    for (int v = 0; v < mesh_.numVertices(); ++v) {
      const std::span<const int> star = ve.of(v);
      if (mesh_.boundary[v] || star.size() != 2) continue;
      const int e = star[0], f = star[1];
      if (!mesh_.isQuad(e) || !mesh_.isQuad(f)) continue;
      const int i = mesh_.cornerIndex(e, v), j = mesh_.cornerIndex(f, v);
      const Corners& a = mesh_.corners[e];
      const Corners& b = mesh_.corners[f];
      // e = (v, x, y, z), f = (v, z, w, x) when v is inner with two quads.
      const int x = a[(i + 1) % 4], y = a[(i + 2) % 4], z = a[(i + 3) % 4];
      if (b[(j + 1) % 4] != z || b[(j + 3) % 4] != x) continue;
      const int w = b[(j + 2) % 4];
      const Corners quad{x, y, z, w};
      if (elementQuality(mesh_, metrics_, quad) <= 0) continue;
      const std::array<int, 2> removed{e, f};
      const std::array<Corners, 1> added{quad};
      mesh_.replacePatch(removed, added);
      ++st_.doublets;
    }
  }

  void countValences() {
    valence_.assign(mesh_.numVertices(), 0);
    ideal_.assign(mesh_.numVertices(), 4);
    std::vector<double> angle(mesh_.numVertices(), 0.0);
    for (int e = 0; e < mesh_.numElements(); ++e) {
      const int n = mesh_.sides(e);
      if (n == 0) continue;
      const Mat2 s = metrics_.element(mesh_.corners[e]);
      for (int k = 0; k < n; ++k) {
        const int v = mesh_.corners[e][k];
        // Each edge counted once from each side; a boundary edge only once, so add it for
        // both endpoints below.
        ++valence_[v];
        if (mesh_.adj[e][k] == kNone) ++valence_[mesh_.corners[e][(k + 1) % n]];
        const Vec2 p = mesh_.uv[v];
        const Vec2 a = s * (mesh_.uv[mesh_.corners[e][(k + 1) % n]] - p);
        const Vec2 b = s * (mesh_.uv[mesh_.corners[e][(k + n - 1) % n]] - p);
        angle[v] += std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      }
    }
    for (int v = 0; v < mesh_.numVertices(); ++v)
      if (mesh_.boundary[v]) ideal_[v] = static_cast<int>(std::lround(angle[v] / (std::numbers::pi / 2))) + 1;
  }

  int deviation(int v, int delta) const {
    const int d = valence_[v] + delta - ideal_[v];
    return d * d;
  }

  void trySwap(int e, int k) {
    const int f = mesh_.adj[e][k];
    if (f == kNone || !mesh_.isQuad(f) || f < e) return;
    const Corners& a = mesh_.corners[e];
    const int u = a[k], v = a[(k + 1) % 4];
    const int j = mesh_.edgeIndex(f, v, u);
    if (j == kNone) return;
    const Corners& b = mesh_.corners[f];
    // Hexagon counter-clockwise: u, f's two far corners, v, e's two far corners.
    const std::array<int, 6> h{u, b[(j + 2) % 4], b[(j + 3) % 4], v, a[(k + 2) % 4], a[(k + 3) % 4]};
    for (int x = 0; x < 6; ++x)
      for (int y = x + 1; y < 6; ++y)
        if (h[x] == h[y]) return;
    auto at = [&](int x) { return h[x % 6]; };
    const double oldWorst = std::min(elementQuality(mesh_, metrics_, a), elementQuality(mesh_, metrics_, b));
    int oldDev = 0;
    for (int x = 0; x < 6; ++x) oldDev += deviation(h[x], 0);
    int best = kNone, bestDev = oldDev;
    double bestWorst = oldWorst;
    std::array<Corners, 2> bestQuads;
    for (int r : {1, 2}) {
      const std::array<Corners, 2> quads{Corners{at(r), at(r + 1), at(r + 2), at(r + 3)},
                                         Corners{at(r + 3), at(r + 4), at(r + 5), at(r)}};
      const double worst = std::min(elementQuality(mesh_, metrics_, quads[0]), elementQuality(mesh_, metrics_, quads[1]));
      if (worst <= 0) continue;
      int dev = 0;
      for (int x = 0; x < 6; ++x) {
        const int vx = h[x];
        const int delta = (vx == u || vx == v) ? -1 : ((vx == at(r) || vx == at(r + 3)) ? 1 : 0);
        dev += deviation(vx, delta);
      }
      const bool valenceWin = dev < bestDev && worst >= std::min(oldWorst, o_.minQuality);
      const bool shapeWin = dev <= bestDev && worst > bestWorst + o_.qualityGain;
      if (valenceWin || shapeWin) {
        best = r;
        bestDev = dev;
        bestWorst = worst;
        bestQuads = quads;
      }
    }
    if (best == kNone) return;
    const std::array<int, 2> removed{e, f};
    mesh_.replacePatch(removed, bestQuads);
    --valence_[u];
    --valence_[v];
    ++valence_[at(best)];
    ++valence_[at(best + 3)];
    ++st_.swaps;
  }

  QuadMesh2d& mesh_;
  VertexMetrics& metrics_;
  const TopologyOptions& o_;
  TopologyStats st_;
  std::vector<int> valence_, ideal_;
};

}  // namespace

TopologyStats improveTopology(QuadMesh2d& mesh, VertexMetrics& metrics, const TopologyOptions& options) {
  return Topology(mesh, metrics, options).run();
}

}  // namespace aniso::quad
