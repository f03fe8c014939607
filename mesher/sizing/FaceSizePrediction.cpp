#include "mesher/sizing/FaceSizePrediction.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesher/surface/face/FaceMetric.h"

namespace aniso {
namespace {

/// Boundary segments bucketed by rows of v, for the winding number of many points.
class WindingIndex {
 public:
  explicit WindingIndex(const FaceBoundary& b) {
    std::size_t n = 0;
    for (const auto& loop : b.loops) n += loop.size();
    rows_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(n))), 1, 4096);
    for (const auto& loop : b.loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec2 a = loop[i].uv, c = loop[(i + 1) % loop.size()].uv;
        lo_ = std::min({lo_, a.y(), c.y()});
        hi_ = std::max({hi_, a.y(), c.y()});
        segs_.push_back({a, c});
      }
    if (segs_.empty()) return;
    buckets_.resize(rows_);
    for (std::size_t s = 0; s < segs_.size(); ++s) {
      const int ra = row(segs_[s].a.y()), rb = row(segs_[s].b.y());
      for (int r = std::min(ra, rb); r <= std::max(ra, rb); ++r) buckets_[r].push_back(static_cast<int>(s));
    }
  }

  /// Winding number of the loops around p (a ray towards +u; half-open rule on v).
  int winding(const Vec2& p) const {
    if (segs_.empty() || p.y() < lo_ || p.y() > hi_) return 0;
    int w = 0;
    for (int s : buckets_[row(p.y())]) {
      const Vec2 &a = segs_[s].a, &b = segs_[s].b;
      const bool up = a.y() <= p.y() && b.y() > p.y(), down = b.y() <= p.y() && a.y() > p.y();
      if (!up && !down) continue;
      const double side = (b.x() - a.x()) * (p.y() - a.y()) - (p.x() - a.x()) * (b.y() - a.y());
      if (up && side > 0) ++w;
      if (down && side < 0) --w;
    }
    return w;
  }

 private:
  struct Seg {
    Vec2 a, b;
  };
  int row(double v) const {
    const double t = hi_ > lo_ ? (v - lo_) / (hi_ - lo_) : 0.0;
    return std::clamp(static_cast<int>(t * rows_), 0, rows_ - 1);
  }
  std::vector<Seg> segs_;
  std::vector<std::vector<int>> buckets_;
  int rows_ = 1;
  double lo_ = std::numeric_limits<double>::infinity(), hi_ = -std::numeric_limits<double>::infinity();
};

}  // namespace

FaceSizePrediction::FaceSizePrediction(const CSQuadtree2d& cs, const FaceBoundary& boundary) {
  smallest_ = std::numeric_limits<double>::infinity();
  const WindingIndex index(boundary);
  const auto& tree = cs.structure().tree();
  for (int leaf : tree.leaves()) {
    const Vec2 lo = tree.nodeLo(leaf), size = tree.nodeSize(leaf);
    const double area = size.x() * size.y() / (kSamplesPerAxis * kSamplesPerAxis);
    for (int i = 0; i < kSamplesPerAxis; ++i)
      for (int j = 0; j < kSamplesPerAxis; ++j) {
        const Vec2 uv = lo + Vec2((i + 0.5) / kSamplesPerAxis * size.x(), (j + 0.5) / kSamplesPerAxis * size.y());
        if (index.winding(uv) == 0) continue;
        const SurfaceMetricAt m = cs.getMetric(uv);
        const MetricAngle2d al = m.sizing.angleLengths();
        const double w = area * std::abs(m.parameterization.determinant());
        if (!(std::isfinite(w) && al.h1 > 0 && al.h2 > 0)) continue;
        samples_.push_back({al.h1, al.h2, w});
        smallest_ = std::min(smallest_, al.h1);
      }
  }
}

double FaceSizePrediction::triangles(double hFloor) const {
  double area = 0;
  for (const Sample& s : samples_) area += s.weight / (std::max(s.h1, hFloor) * std::max(s.h2, hFloor));
  return area / face::kIdealTriangleArea;
}

double FaceSizePrediction::area() const {
  double a = 0;
  for (const Sample& s : samples_) a += s.weight;
  return a;
}

int applySizeFloor(CSAdaptive2d& cs, double hFloor) {
  int changed = 0;
  cs.modifyControlVertices([&](const Vec2&, Metric2d& m) {
    const MetricAngle2d al = m.angleLengths();
    if (al.h1 >= hFloor && al.h2 >= hFloor) return false;
    m = Metric2d::fromAngle(al.alpha, std::max(al.h1, hFloor), std::max(al.h2, hFloor));
    ++changed;
    return true;
  });
  return changed;
}

}  // namespace aniso
