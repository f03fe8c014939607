#include "mesher/quad/BoundaryPostprocess.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "mesher/quad/QuadSmoothing.h"

namespace aniso::quad {
namespace {

struct Interval {
  double low, high;
};

bool touchesBoundary(const QuadMesh2d& mesh, int e) {
  for (int k = 0; k < mesh.sides(e); ++k)
    if (mesh.boundary[mesh.corners[e][k]]) return true;
  return false;
}

/// Trial `t` beats `current`: every element valid, neither the worst element nor the worst
/// quad drops, and worst + meanWeight × mean rises by more than minGain (the mean breaks
/// ties between positions the worst cannot tell apart: pure max–min trades the good quads of
/// the star for the poor one).
bool beats(const StarQuality& t, const StarQuality& current, const BoundaryPostprocessOptions& o) {
  return t.valid && t.worst >= current.worst && t.worstQuad >= current.worstQuad &&
         t.worst + o.meanWeight * t.mean > current.worst + o.meanWeight * current.mean + o.minGain;
}

/// The compass search of one vertex (see the header); leaves mesh.uv[v] at the best
/// position found.
void searchVertex(QuadMesh2d& mesh, VertexMetrics& metrics, int v, std::span<const int> star,
                  const Vec2& origin, double floor, StarQuality score, const BoundaryPostprocessOptions& o) {
  const Mat2 s = metrics.at(v);
  if (!(std::abs(s.determinant()) > 0)) return;
  const Mat2 sInverse = s.inverse();
  constexpr int kDirections = 8;
  constexpr int kMaxTrials = 48;  // bounds the work per vertex and sweep
  // The scaled Jacobian is blind to size: a vertex may slide next to a boundary vertex and
  // leave perfect but tiny rectangles. The edges at v keep their metric length within
  // [min(floor, now), max(longestEdge, now)].
  std::vector<std::pair<int, Interval>> edges;
  for (int e : star) {
    const int n = mesh.sides(e), k = mesh.cornerIndex(e, v);
    for (int nb : {mesh.corners[e][(k + 1) % n], mesh.corners[e][(k + n - 1) % n]}) {
      if (std::any_of(edges.begin(), edges.end(), [&](const auto& x) { return x.first == nb; })) continue;
      const double l = metrics.length(v, nb);
      edges.emplace_back(nb, Interval{std::min(floor, l), std::max(o.longestEdge, l)});
    }
  }
  auto sizesKept = [&] {
    return std::all_of(edges.begin(), edges.end(), [&](const auto& x) {
      const double l = metrics.length(v, x.first);
      return l >= x.second.low && l <= x.second.high;
    });
  };
  Vec2 current = mesh.uv[v];
  int trials = 0;
  for (double step = o.initialStep; step >= o.finalStep && trials < kMaxTrials;) {
    Vec2 best = current;
    StarQuality bestScore = score;
    for (int k = 0; k < kDirections; ++k, ++trials) {
      const double angle = 2.0 * std::numbers::pi * k / kDirections;
      const Vec2 trial = current + step * (sInverse * Vec2(std::cos(angle), std::sin(angle)));
      if (!((s * (trial - origin)).norm() <= o.maxDisplacement)) continue;
      mesh.uv[v] = trial;
      metrics.refreshPoint(v);
      if (!sizesKept()) continue;
      const StarQuality t = starQuality(mesh, metrics, star);
      if (beats(t, bestScore, o)) {
        bestScore = t;
        best = trial;
      }
    }
    if (best != current) {
      current = best;
      score = bestScore;
    } else {
      step *= 0.5;
    }
  }
  mesh.uv[v] = current;
  metrics.refreshPoint(v);
}

}  // namespace

double worstBoundaryLayerQuality(const QuadMesh2d& mesh, VertexMetrics& metrics) {
  double worst = 2;
  for (int e = 0; e < mesh.numElements(); ++e)
    if (mesh.alive(e) && touchesBoundary(mesh, e)) worst = std::min(worst, elementQuality(mesh, metrics, mesh.corners[e]));
  return worst;
}

BoundaryPostprocessStats postprocessBoundaryLayer(QuadMesh2d& mesh, VertexMetrics& metrics,
                                                  const BoundaryPostprocessOptions& o) {
  BoundaryPostprocessStats st;
  st.worstBefore = worstBoundaryLayerQuality(mesh, metrics);
  VertexElements ve;
  ve.build(mesh);
  const std::vector<std::uint8_t> frozen = frozenVertices(mesh);
  std::vector<int> layer;  // free vertices with an element of the boundary layer in their star
  for (int v = 0; v < mesh.numVertices(); ++v) {
    if (frozen[v]) continue;
    const std::span<const int> star = ve.of(v);
    if (std::any_of(star.begin(), star.end(), [&](int e) { return touchesBoundary(mesh, e); })) layer.push_back(v);
  }
  std::vector<Vec2> origin;
  std::vector<double> floor;  // shortestEdge × the shortest metric edge of the star on entry
  origin.reserve(layer.size());
  floor.reserve(layer.size());
  for (int v : layer) {
    origin.push_back(mesh.uv[v]);
    double shortest = std::numeric_limits<double>::infinity();
    for (int e : ve.of(v))
      for (int k = 0, n = mesh.sides(e); k < n; ++k)
        shortest = std::min(shortest, metrics.length(mesh.corners[e][k], mesh.corners[e][(k + 1) % n]));
    floor.push_back(o.shortestEdge * shortest);
  }
  std::vector<std::uint8_t> counted(layer.size(), 0);
  for (int sweep = 0; sweep < o.sweeps; ++sweep) {
    std::vector<int> moved;
    for (std::size_t i = 0; i < layer.size(); ++i) {
      const int v = layer[i];
      const std::span<const int> star = ve.of(v);
      const StarQuality score = starQuality(mesh, metrics, star);
      if (!score.valid || score.worst >= o.careBelow) continue;
      if (!counted[i]) {
        counted[i] = 1;
        ++st.candidates;
      }
      const Vec2 before = mesh.uv[v];
      searchVertex(mesh, metrics, v, star, origin[i], floor[i], score, o);
      if (mesh.uv[v] != before) {
        ++st.moved;
        moved.push_back(v);
      }
    }
    for (int v : moved) metrics.invalidate(v);
    if (moved.empty()) break;
  }
  st.worstAfter = worstBoundaryLayerQuality(mesh, metrics);
  return st;
}

}  // namespace aniso::quad
