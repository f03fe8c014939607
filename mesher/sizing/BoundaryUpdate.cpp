#include "mesher/sizing/BoundaryUpdate.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/core/Segment.h"

namespace aniso {
namespace {

struct Segment {
  Vec2 a, b;
  int loop, index;  ///< position in the loops
  double along;     ///< real length along the loop from its first node to the midpoint
};

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

/// Two segments of one loop that the loop joins by a path not much longer than the
/// straight distance between them are neighbours around a corner, not two sides of a gap:
/// a gap needs the boundary to go away and come back (path > kGapPathRatio × distance).
/// With 3, corners sharper than about 40° count as gaps and get graded refinement.
constexpr double kGapPathRatio = 3.0;

bool sameSideOfGap(const Segment& s, const Segment& t, double distance, const std::vector<double>& loopLength) {
  if (s.loop != t.loop) return false;
  const double d = std::abs(s.along - t.along);
  const double path = std::min(d, loopLength[s.loop] - d);
  return path <= kGapPathRatio * distance;
}

}  // namespace

/// Would intersecting the control space's metric at `at` with m change it by more than
/// eps (δ_M)? Sources that change nothing are not inserted, so the rounds of alg. 3.1 stop.
bool wouldChange(const CSAdaptive2d& cs, const Vec2& at, const Metric2d& m, double eps);

BoundaryUpdateStats updateFromBoundary(CSAdaptive2d& cs, const FaceBoundary& boundary,
                                       const SizingParameters& params, const BoundaryUpdateOptions& options) {
  const double hMin = options.hMin;
  BoundaryUpdateStats stats;
  const double lMin = 1.0 / params.adaptLengthMax;  // 1 / l_Mmax
  std::vector<Segment> segs;
  std::vector<double> loopLength;
  Box2 box;
  for (int l = 0; l < static_cast<int>(boundary.loops.size()); ++l) {
    const auto& loop = boundary.loops[l];
    const int n = static_cast<int>(loop.size());
    double along = 0;
    for (int i = 0; i < n; ++i) {
      const BoundaryNode& a = loop[i];
      const BoundaryNode& b = loop[(i + 1) % n];
      const Vec2 mid = 0.5 * (a.uv + b.uv);
      const double len = (cs.getMetric(mid).parameterization * (b.uv - a.uv)).norm();
      if (a.node != b.node) segs.push_back({a.uv, b.uv, l, i, along + 0.5 * len});  // skip pole pieces
      along += len;
      box.add(a.uv);
      box.add(b.uv);
    }
    loopLength.push_back(along);
  }
  if (segs.empty()) return stats;
  const SegmentGrid grid(segs, box);
  // A source covers a whole boundary segment, not just its midpoint: control elements can
  // be much smaller than a segment in (u, v) (a strip thin in u but long in v), and a
  // single point source would then refine only around itself.
  struct Source {
    Vec2 a, b;
    double r;
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
      const Metric2d src = Metric2d::isotropic(std::max(lenReal, hMin));
      if (wouldChange(cs, mid, src, params.metricDifferenceEps)) {
        sources.push_back({sg.a, sg.b, 0.0, src});
        ++stats.shortSegments;
      }
    }
    if (!options.vicinity) continue;
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
    int bestSeg = -1;
    grid.forCells(q, [&](int c) {
      for (int t : grid.cell(c)) {
        if (t == s || stamp[t] == s) continue;
        stamp[t] = s;
        const Vec2 p = closestPointOnSegment<Vec2>(mid, segs[t].a, segs[t].b);
        const double d = (m * (p - mid)).norm();
        if (d < best && !sameSideOfGap(sg, segs[t], (mp * (p - mid)).norm(), loopLength)) {
          best = d;
          bestAt = p;
          bestSeg = t;
        }
      }
    });
    if (best < lMin) {
      // Elements no longer than the gap across it, at most γ_a times that along it.
      const Vec2 across = mp * (bestAt - mid);
      const double gap = std::max(across.norm(), hMin);
      const double angle = std::atan2(across.y(), across.x());
      const Metric2d g = Metric2d::fromAngle(angle, gap, gap * params.anisotropy);
      const bool a = wouldChange(cs, mid, g, params.metricDifferenceEps);
      const bool b = wouldChange(cs, bestAt, g, params.metricDifferenceEps);
      if (a) sources.push_back({sg.a, sg.b, 0.0, g});
      if (b) sources.push_back({segs[bestSeg].a, segs[bestSeg].b, 0.0, g});
      stats.gaps += (a || b);
    }
  }
  for (const Source& src : sources) {
    // The segment's ends and midpoint as point sources (an extended source would scan
    // every control vertex per source, too slow for thousands of segments).
    cs.insertDiscreteSource(src.a, src.m);
    cs.insertDiscreteSource(0.5 * (src.a + src.b), src.m);
    cs.insertDiscreteSource(src.b, src.m);
  }
  return stats;
}

bool wouldChange(const CSAdaptive2d& cs, const Vec2& at, const Metric2d& m, double eps) {
  const Metric2d current = cs.getMetric(at).sizing;
  return metricDifference(intersect(current, m), current) > eps;
}

}  // namespace aniso
