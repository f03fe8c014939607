#include "mesher/sizing/BoundaryUpdate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/LU>
#include <Eigen/SVD>

namespace aniso {
namespace {

struct Segment {
  Vec2 a, b;
  int loop, index;  ///< position in the loops
};

/// Closest point to p on segment [a, b] (in the coordinates given).
Vec2 closestOnSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

/// Bucket grid over the segments' (u, v) boxes.
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<Segment>& segs, const Box2& box) : segs_(segs), box_(box) {
    const int n = static_cast<int>(segs.size());
    const double cells = std::max(1.0, std::sqrt(static_cast<double>(n)));
    const Vec2 size = box.size().cwiseMax(1e-300);
    nx_ = std::clamp(static_cast<int>(cells * size.x() / size.maxCoeff()), 1, 1024);
    ny_ = std::clamp(static_cast<int>(cells * size.y() / size.maxCoeff()), 1, 1024);
    cellsOf_.assign(static_cast<size_t>(nx_) * ny_, {});
    for (int s = 0; s < n; ++s) {
      Box2 sb;
      sb.add(segs[s].a);
      sb.add(segs[s].b);
      forCells(sb, [&](int c) { cellsOf_[c].push_back(s); });
    }
  }
  template <class F>
  void forCells(const Box2& q, F f) const {
    const auto ix = [&](double x) { return std::clamp(static_cast<int>((x - box_.lo.x()) / (box_.size().x() + 1e-300) * nx_), 0, nx_ - 1); };
    const auto iy = [&](double y) { return std::clamp(static_cast<int>((y - box_.lo.y()) / (box_.size().y() + 1e-300) * ny_), 0, ny_ - 1); };
    for (int j = iy(q.lo.y()); j <= iy(q.hi.y()); ++j)
      for (int i = ix(q.lo.x()); i <= ix(q.hi.x()); ++i) f(j * nx_ + i);
  }
  const std::vector<int>& cell(int c) const { return cellsOf_[c]; }

 private:
  const std::vector<Segment>& segs_;
  Box2 box_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cellsOf_;
};

bool adjacentInLoop(const Segment& s, const Segment& t, const std::vector<std::vector<BoundaryNode>>& loops) {
  if (s.loop != t.loop) return false;
  const int n = static_cast<int>(loops[s.loop].size());
  const int d = std::abs(s.index - t.index);
  return std::min(d, n - d) <= 1;
}

}  // namespace

BoundaryUpdateStats updateFromBoundary(CSAdaptive2d& cs, const FaceBoundary& boundary,
                                       const SizingParameters& params, double hMin) {
  BoundaryUpdateStats stats;
  const double lMin = 1.0 / params.adaptLengthMax;  // 1 / l_Mmax
  std::vector<Segment> segs;
  Box2 box;
  for (int l = 0; l < static_cast<int>(boundary.loops.size()); ++l) {
    const auto& loop = boundary.loops[l];
    const int n = static_cast<int>(loop.size());
    for (int i = 0; i < n; ++i) {
      const BoundaryNode& a = loop[i];
      const BoundaryNode& b = loop[(i + 1) % n];
      if (a.node == b.node) continue;  // a piece of a pole
      segs.push_back({a.uv, b.uv, l, i});
      box.add(a.uv);
      box.add(b.uv);
    }
  }
  if (segs.empty()) return stats;
  const SegmentGrid grid(segs, box);
  struct Source {
    Vec2 at;
    Metric2d m;
  };
  std::vector<Source> sources;
  std::vector<int> stamp(segs.size(), -1);
  for (int s = 0; s < static_cast<int>(segs.size()); ++s) {
    const Segment& sg = segs[s];
    const Vec2 mid = 0.5 * (sg.a + sg.b);
    const SurfaceMetricAt at = cs.getMetric(mid);
    const Mat2 m = at.transformation();
    const Mat2& mp = at.parameterization;
    const Vec2 dR = mp * (sg.b - sg.a);  // the segment in S^R (real length)
    const double lenReal = dR.norm();
    if (lenReal <= 0) continue;
    // Segment length in the face's metric.
    if ((m * (sg.b - sg.a)).norm() < lMin) {
      const double h = std::max(lenReal, hMin);
      sources.push_back({mid, Metric2d::isotropic(h)});
      ++stats.shortSegments;
    }
    // Vicinity: other segments closer than lMin in the metric. The search radius in (u, v)
    // is the longest (u, v) vector of metric length lMin: lMin / σ_min(M).
    const Eigen::JacobiSVD<Mat2> svd(m);
    const double sMin = svd.singularValues()(1);
    if (!(sMin > 0)) continue;
    const double r = lMin / sMin;
    Box2 q;
    q.add(mid - Vec2(r, r));
    q.add(mid + Vec2(r, r));
    double best = lMin;
    Vec2 bestAt = mid;
    grid.forCells(q, [&](int c) {
      for (int t : grid.cell(c)) {
        if (t == s || stamp[t] == s) continue;
        stamp[t] = s;
        if (adjacentInLoop(sg, segs[t], boundary.loops)) continue;
        const Vec2 p = closestOnSegment(mid, segs[t].a, segs[t].b);
        const double d = (m * (p - mid)).norm();
        if (d < best) {
          best = d;
          bestAt = p;
        }
      }
    });
    if (best < lMin) {
      // Elements no longer than the gap across it, at most γ_a times that along it.
      const Vec2 across = mp * (bestAt - mid);
      const double gap = std::max(across.norm(), hMin);
      const double angle = std::atan2(across.y(), across.x());
      const Metric2d g = Metric2d::fromAngle(angle, gap, gap * params.anisotropy);
      sources.push_back({mid, g});
      sources.push_back({bestAt, g});
      ++stats.gaps;
    }
  }
  for (const Source& src : sources) cs.insertDiscreteSource(src.at, src.m);
  return stats;
}

}  // namespace aniso
