#include "mesher/sizing/UserSizing.h"

#include <algorithm>

#include <Eigen/LU>

#include "mesher/metric/MetricIntersection.h"
#include "mesher/core/Segment.h"

namespace aniso {
bool SizingSource::contains(const Vec3& x) const {
  switch (kind) {
    case Kind::Point: return (x - a).norm() <= radius;
    case Kind::Segment: return distanceToSegment(x, a, b) <= radius;
    case Kind::Box: return (x.array() >= a.array()).all() && (x.array() <= b.array()).all();
  }
  return false;
}

Box3 SizingSource::bounds() const {
  Box3 box;
  box.add(a);
  if (kind != Kind::Point) box.add(b);
  const double r = kind == Kind::Box ? 0.0 : radius;
  box.lo.array() -= r;
  box.hi.array() += r;
  return box;
}

bool SizingSource::sizesFace(int f) const { return faces.empty() || std::binary_search(faces.begin(), faces.end(), f); }

std::optional<Metric3d> UserSizing::metricAt(const Vec3& x) const {
  std::optional<Metric3d> m = global;
  for (const SizingSource& s : sources) {
    if (!s.faces.empty() || !s.contains(x)) continue;
    m = m ? intersect(*m, s.metric) : s.metric;
  }
  return m;
}

namespace {
Metric3d boundedMetric(const Metric3d& m, double hmin, double hmax) {
  MetricAxes<3> ax = m.axes();
  ax.lengths = ax.lengths.cwiseMax(hmin).cwiseMin(hmax);
  return Metric3d::fromAxes(ax.directions, ax.lengths);
}
}  // namespace

UserSizing UserSizing::bounded(double hmin, double hmax) const {
  UserSizing out = *this;
  if (out.global) out.global = boundedMetric(*out.global, hmin, hmax);
  for (SizingSource& s : out.sources) s.metric = boundedMetric(s.metric, hmin, hmax);
  return out;
}

Metric2d restrictToSurface(const Metric3d& m3, const Vec3& pu, const Vec3& pv, const Mat2& mp) {
  Eigen::Matrix<double, 3, 2> j;
  j.col(0) = pu;
  j.col(1) = pv;
  const Mat2 mpInv = mp.inverse();
  const Eigen::Matrix<double, 3, 2> mj = m3.matrix() * j * mpInv;
  Mat2 t = mj.transpose() * mj;
  // where J is nearly singular (a parametric direction of almost no length in space: a
  // pole, a collapsed edge) the tensor's small eigenvalue is below the rounding of the large
  // one; the floor keeps it positive (and leaves any other tensor unchanged to 1e-10)
  t += (kRestrictedTensorFloor * t.trace()) * Mat2::Identity();
  return Metric2d::fromTensor(t);
}

}  // namespace aniso
