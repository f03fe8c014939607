#include "mesher/sizing/BoundaryGaps.h"

#include <algorithm>
#include <cmath>

#include <Eigen/SVD>

#include "mesher/core/Segment.h"
#include "mesher/predicates/Predicates.h"

namespace aniso {
namespace {

/// Path along the loop / straight distance above which two segments of one loop are two
/// sides of a gap (see the header).
constexpr double kGapPathRatio = 3.0;

/// Bucket grid over the segments' (u, v) boxes.
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<BoundarySegment>& segs, const Box2& box) : box_(box) {
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
    const Vec2 size = box_.size() + Vec2::Constant(1e-300);
    const auto ix = [&](double x) { return std::clamp(static_cast<int>((x - box_.lo.x()) / size.x() * nx_), 0, nx_ - 1); };
    const auto iy = [&](double y) { return std::clamp(static_cast<int>((y - box_.lo.y()) / size.y() * ny_), 0, ny_ - 1); };
    for (int j = iy(q.lo.y()); j <= iy(q.hi.y()); ++j)
      for (int i = ix(q.lo.x()); i <= ix(q.hi.x()); ++i) f(j * nx_ + i);
  }
  const std::vector<int>& cell(int c) const { return cellsOf_[c]; }

 private:
  Box2 box_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cellsOf_;
};

/// Is the point of t at parameter `at` ∈ [0, 1] (closestSegmentParameter) on the same side
/// as the point `along` of loop `loop`, `distance` away?
bool sameSideOfGap(int loop, double along, const BoundarySegment& t, double at, double distance,
                   const std::vector<double>& loopLength) {
  if (loop != t.loop) return false;
  const double d = std::abs(along - (t.along + (at - 0.5) * t.length));
  const double path = std::min(d, loopLength[loop] - d);
  return path <= kGapPathRatio * distance;
}

/// The nearest point (in the metric m) of another side than the boundary point x (at
/// `along` on loop `loop`, on segment `self`), searched within r in (u, v), that is
/// closer than lMin in m or than minWidth in space (M_p = mp).
struct Nearest {
  int segment = -1;
  Vec2 at;
  double metric = HUGE_VAL;
};
Nearest nearestOtherSide(const BoundarySegments& bs, const SegmentGrid& grid, std::vector<int>& stamp, int stampId,
                         int self, const Vec2& x, int loop, double along, const Mat2& m, const Mat2& mp, double r,
                         double lMin, double minWidth) {
  const std::vector<BoundarySegment>& segs = bs.segments;
  Box2 q;
  q.add(x - Vec2(r, r));
  q.add(x + Vec2(r, r));
  Nearest best;
  grid.forCells(q, [&](int c) {
    for (int t : grid.cell(c)) {
      if (t == self || stamp[t] == stampId) continue;
      stamp[t] = stampId;
      const double param = closestSegmentParameter<Vec2>(x, segs[t].a, segs[t].b);
      const Vec2 p = segs[t].a + param * (segs[t].b - segs[t].a);
      const double d = (m * (p - x)).norm();
      const double real = (mp * (p - x)).norm();
      if (d < best.metric && (d < lMin || real < minWidth) &&
          !sameSideOfGap(loop, along, segs[t], param, real, bs.loopLength)) {
        best.metric = d;
        best.at = p;
        best.segment = t;
      }
    }
  });
  return best;
}

}  // namespace

BoundarySegments boundarySegments(const ControlSpace2d& cs, const FaceBoundary& boundary) {
  BoundarySegments out;
  for (int l = 0; l < static_cast<int>(boundary.loops.size()); ++l) {
    const auto& loop = boundary.loops[l];
    const int n = static_cast<int>(loop.size());
    out.loopFirst.push_back(static_cast<int>(out.segments.size()));
    double along = 0;
    for (int i = 0; i < n; ++i) {
      const BoundaryNode& a = loop[i];
      const BoundaryNode& b = loop[(i + 1) % n];
      const double len = (cs.getMetric(0.5 * (a.uv + b.uv)).parameterization * (b.uv - a.uv)).norm();
      if (a.node != b.node) out.segments.push_back({a.uv, b.uv, l, along + 0.5 * len, len});  // skip pole pieces
      along += len;
      out.box.add(a.uv);
      out.box.add(b.uv);
    }
    out.loopLength.push_back(along);
  }
  out.loopFirst.push_back(static_cast<int>(out.segments.size()));
  return out;
}

std::vector<BoundaryGap> findBoundaryGaps(const ControlSpace2d& cs, const BoundarySegments& bs, double lMin,
                                          double minWidth) {
  std::vector<BoundaryGap> gaps;
  const std::vector<BoundarySegment>& segs = bs.segments;
  if (segs.empty()) return gaps;
  const SegmentGrid grid(segs, bs.box);
  std::vector<int> stamp(segs.size(), -1);  // per-query marks: segments seen through several cells
  for (int s = 0; s < static_cast<int>(segs.size()); ++s) {
    const BoundarySegment& sg = segs[s];
    const Vec2 mid = 0.5 * (sg.a + sg.b);
    const SurfaceMetricAt at = cs.getMetric(mid);
    const Mat2 m = at.transformation();
    const Mat2& mp = at.parameterization;
    // Search radius in (u, v): the longest (u, v) vector of metric length lMin (lMin / σ_min(M))
    // or of real length minWidth (minWidth / σ_min(M_p)).
    const double sMin = Eigen::JacobiSVD<Mat2>(m).singularValues()(1);
    const double sMinP = Eigen::JacobiSVD<Mat2>(mp).singularValues()(1);
    if (!(sMin > 0) || !(sMinP > 0)) continue;
    const double r = std::max(lMin / sMin, minWidth / sMinP);
    const Nearest n = nearestOtherSide(bs, grid, stamp, s, s, mid, sg.loop, sg.along, m, mp, r, lMin, minWidth);
    if (n.segment < 0) continue;
    BoundaryGap g;
    g.segment = s;
    g.other = n.segment;
    g.at = n.at;
    g.metricWidth = n.metric;
    g.across = mp * (n.at - mid);
    gaps.push_back(g);
  }
  return gaps;
}

double thinFaceWidth(const BoundarySegments& segs, const std::vector<BoundaryGap>& gaps, double cap) {
  double total = 0, weighted = 0;
  for (const BoundarySegment& s : segs.segments) {
    total += s.length;
    weighted += s.length * cap;
  }
  for (const BoundaryGap& g : gaps) {
    const double len = segs.segments[g.segment].length;
    weighted -= len * (cap - std::min(g.width(), cap));
  }
  return total > 0 ? weighted / total : cap;
}

namespace {

/// c lies strictly inside the segment ab, the three collinear (orientation 0).
bool insideCollinear(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 d = b - a;
  const double t = (c - a).dot(d);
  return t > 0 && t < d.squaredNorm();
}

/// s and t cross, or an end of one touches the other's interior; a shared end is no contact.
bool segmentsMeet(const BoundarySegment& s, const BoundarySegment& t) {
  const bool sharedEnd = s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b;
  using predicates::orient2d;
  const double o1 = orient2d(s.a.data(), s.b.data(), t.a.data()), o2 = orient2d(s.a.data(), s.b.data(), t.b.data());
  const double o3 = orient2d(t.a.data(), t.b.data(), s.a.data()), o4 = orient2d(t.a.data(), t.b.data(), s.b.data());
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  if (sharedEnd) return false;
  return (o1 == 0 && insideCollinear(s.a, s.b, t.a)) || (o2 == 0 && insideCollinear(s.a, s.b, t.b)) ||
         (o3 == 0 && insideCollinear(t.a, t.b, s.a)) || (o4 == 0 && insideCollinear(t.a, t.b, s.b));
}

}  // namespace

std::vector<int> crossingSegments(const BoundarySegments& bs) {
  const auto& segs = bs.segments;
  const int n = static_cast<int>(segs.size());
  std::vector<char> crossing(static_cast<std::size_t>(n), 0);
  if (n < 3) return {};
  const SegmentGrid grid(segs, bs.box);
  std::vector<int> stamp(static_cast<std::size_t>(n), -1);
  for (int s = 0; s < n; ++s) {
    Box2 sb;
    sb.add(segs[s].a);
    sb.add(segs[s].b);
    grid.forCells(sb, [&](int c) {
      for (const int t : grid.cell(c)) {
        if (t <= s || stamp[t] == s) continue;  // each pair once
        stamp[t] = s;
        if (segmentsMeet(segs[s], segs[t])) crossing[s] = crossing[t] = 1;
      }
    });
  }
  std::vector<int> out;
  for (int s = 0; s < n; ++s)
    if (crossing[s]) out.push_back(s);
  return out;
}

}  // namespace aniso
