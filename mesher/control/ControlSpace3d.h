#pragma once
// ControlSpace3d — the control space for volume meshing (sec. 3.2, 6.3.2, fig. 6.5):
// returns the transformation tensor M = M_s (eq. 2.16) at any point of space.
// Thread safety as ControlSpace2d.
#include <cstdint>
#include <memory>

#include "mesher/core/Types.h"
#include "mesher/metric/Metric.h"

namespace aniso {

class ControlSpace3d {
 public:
  virtual ~ControlSpace3d() = default;
  /// The metric at point x (points outside bounds() get the metric of the nearest point
  /// of the box).
  virtual Metric3d getMetric(const Vec3& x) const = 0;
  virtual Box3 bounds() const = 0;
  /// A value that changes whenever the metric field changes (adaptive control spaces);
  /// constant for immutable ones. Lets query caches (MetricQueryCache.h) detect staleness.
  virtual std::uint64_t revision() const { return 0; }
};

using ControlSpace3dPtr = std::shared_ptr<ControlSpace3d>;

}  // namespace aniso
