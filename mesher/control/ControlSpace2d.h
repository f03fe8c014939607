#pragma once
// ControlSpace2d — the thesis' control space for surface meshing (sec. 3.2, 6.3.1, fig. 6.4):
// returns, at any point of a face's parametric domain, the metric that the mesh must follow.
//
// The sizing component M_s (Metric2d, acting on S^R vectors, see mesher/metric/Metric.h)
// and the parameterization tensor M_p of the face at that point are returned together; the
// transformation used by the mesher is M = M_s M_p (eq. 2.9). Control spaces that know no
// surface (e.g. for planar analytic models) return M_p = I.
//
// Thread safety: getMetric() is const and must be safe to call from several threads at
// once on a control space that is no longer being modified.
#include <cstdint>
#include <memory>

#include "mesher/core/Types.h"
#include "mesher/metric/Metric.h"

namespace aniso {

struct SurfaceMetricAt {
  Metric2d sizing;                    ///< M_s
  Mat2 parameterization = Mat2::Identity();  ///< M_p
  /// M = M_s M_p
  Mat2 transformation() const { return sizing.matrix() * parameterization; }
};

class ControlSpace2d {
 public:
  virtual ~ControlSpace2d() = default;
  /// The metric at parametric point uv (points outside the domain get the metric of the
  /// nearest point of the domain).
  virtual SurfaceMetricAt getMetric(const Vec2& uv) const = 0;
  /// The parametric rectangle this control space covers.
  virtual Box2 bounds() const = 0;
  /// A value that changes whenever the metric field changes (adaptive control spaces);
  /// constant for immutable ones. Lets query caches (MetricQueryCache.h) detect staleness.
  virtual std::uint64_t revision() const { return 0; }
};

using ControlSpace2dPtr = std::shared_ptr<ControlSpace2d>;

}  // namespace aniso
