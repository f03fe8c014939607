#pragma once
// CSIdentity2d / CSIdentity3d — the Euclidean control space used internally (sec. 6.3.1):
// M_s = I (unit lengths) everywhere, M_p = I in 2D; for auxiliary meshes such as the
// background mesh of a control space. Immutable, thread-safe, header-only.
#include "mesher/control/ControlSpace2d.h"
#include "mesher/control/ControlSpace3d.h"

namespace aniso {

class CSIdentity2d final : public ControlSpace2d {
 public:
  explicit CSIdentity2d(const Box2& bounds) : bounds_(bounds) {}
  SurfaceMetricAt getMetric(const Vec2&) const override { return {}; }
  Box2 bounds() const override { return bounds_; }

 private:
  Box2 bounds_;
};

class CSIdentity3d final : public ControlSpace3d {
 public:
  explicit CSIdentity3d(const Box3& bounds) : bounds_(bounds) {}
  Metric3d getMetric(const Vec3&) const override { return Metric3d::identity(); }
  Box3 bounds() const override { return bounds_; }

 private:
  Box3 bounds_;
};

}  // namespace aniso
