// Adaptive polyline by recursive bisection with a chord-deviation criterion.
#include "mesher/geometry/AdaptivePolyline.h"

#include <algorithm>
#include <cmath>

#include "mesher/core/Segment.h"
namespace aniso {

namespace {

struct Refiner {
  const std::function<Vec3(double)>& point;
  double tol;
  double absFloor;  ///< deviations below this are round-off (relative to the curve size)
  std::vector<double>& out;

  /// Appends the parameters of (a, b] to out.
  void run(double a, const Vec3& pa, double b, const Vec3& pb, int depth) {
    const double m = 0.5 * (a + b);
    const Vec3 pm = point(m);
    const bool tiny = !(std::abs(b - a) > 1e-13 * std::max({1.0, std::abs(a), std::abs(b)}));
    if (depth > 0 && !tiny) {
      const double chord = (pb - pa).norm();
      const double dev = std::max({distanceToSegment(pm, pa, pb),
                                   distanceToSegment(point(0.75 * a + 0.25 * b), pa, pb),
                                   distanceToSegment(point(0.25 * a + 0.75 * b), pa, pb)});
      if (dev > tol * chord + absFloor || !std::isfinite(dev)) {
        run(a, pa, m, pm, depth - 1);
        run(m, pm, b, pb, depth - 1);
        return;
      }
    }
    out.push_back(b);
  }
};

}  // namespace

std::vector<double> adaptivePolyline(const std::function<Vec3(double)>& point, double t0,
                                     double t1, double tol, int initial, int maxDepth) {
  std::vector<double> out{t0};
  if (t0 == t1) {
    out.push_back(t1);
    return out;
  }
  const int n = std::max(1, initial);
  std::vector<Vec3> pts(n + 1);
  std::vector<double> ts(n + 1);
  Box3 box;
  for (int i = 0; i <= n; ++i) {
    ts[i] = i == n ? t1 : t0 + (t1 - t0) * i / n;
    pts[i] = point(ts[i]);
    if (pts[i].allFinite()) box.add(pts[i]);
  }
  const double absFloor = 1e-12 * std::max(box.diagonal(), 1e-300);
  Refiner r{point, std::max(tol, 1e-12), absFloor, out};
  for (int i = 0; i < n; ++i) r.run(ts[i], pts[i], ts[i + 1], pts[i + 1], maxDepth);
  return out;
}

}  // namespace aniso
