#include "mesher/metric/NonConformity.h"

#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/SimplexMetric.h"

namespace aniso {

double nonConformity(const Metric2d& prescribed, const Vec2& p1, const Vec2& p2, const Vec2& p3) {
  return metricDifference(simplexMetric(p1, p2, p3), prescribed);  // eq. 2.50
}

double nonConformitySurface(const Metric2d& prescribedSizing, const Mat2& mp, const Vec2& p1,
                            const Vec2& p2, const Vec2& p3) {
  return nonConformity(prescribedSizing, Vec2(mp * p1), Vec2(mp * p2), Vec2(mp * p3));
}

double nonConformity(const Metric3d& prescribed, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                     const Vec3& p4) {
  return metricDifference(simplexMetric(p1, p2, p3, p4), prescribed);
}

}  // namespace aniso
