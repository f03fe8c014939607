#pragma once
// QuadSizedSpace — the control space the triangles of a --quad mesh are made in: every
// requested length multiplied by kQuadSizeFactor = (2/√3)^{1/2} ≈ 1.0746, so that two
// merged triangles of unit edge in this space cover the area of the unit square of the real
// metric (2 · √3/4 · l² = 1). Without it the quads, once smoothed towards squares, have
// edges of about 0.93 in the real metric (docs/measurements.md; thesis table A.1). The
// conversion itself and every quality figure use the real control space.
// Read-only view; thread-safe when the wrapped space is.
#include "mesher/control/ControlSpace2d.h"

namespace aniso::quad {

inline constexpr double kQuadSizeFactor = 1.07456993182354;  // sqrt(2 / sqrt(3))

class QuadSizedSpace final : public ControlSpace2d {
 public:
  explicit QuadSizedSpace(const ControlSpace2d& real) : real_(real) {}
  SurfaceMetricAt getMetric(const Vec2& uv) const override {
    SurfaceMetricAt m = real_.getMetric(uv);
    m.sizing = m.sizing.scaled(1.0 / kQuadSizeFactor);
    return m;
  }
  Box2 bounds() const override { return real_.bounds(); }
  std::uint64_t revision() const override { return real_.revision(); }

 private:
  const ControlSpace2d& real_;
};

}  // namespace aniso::quad
