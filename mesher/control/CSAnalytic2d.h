#pragma once
// CSAnalytic2d — a control space whose metric is given by functions (sec. 6.3.1,
// "analytic formulation"): a global function f_0 over the whole domain and optional
// functions f_i over rectangular sub-domains, evaluated directly without interpolation.
// Used for the user's analytic sizing and as an intermediate metric source that is
// superposed onto an adaptive control space (CSAdaptive2d::setContinuousSource / superpose).
//
// A function is any callable uv → Metric2d (the sizing component M_s in S^R); a
// MetricExpression2d (α, h1, h2 in u, v; eq. 2.4 / A.1) is one. At uv the last added
// sub-domain containing uv decides, else f_0. Points outside bounds() are moved to the
// nearest point of bounds() first (ControlSpace2d contract).
// The parameterization tensor: with a surface, M_p = surface.parameterizationTensor(uv,
// gMin), evaluated on a per-thread clone of the surface; without one, M_p = I.
// Thread safety: getMetric() is safe concurrently provided the functions are (a
// MetricExpression2d is; a user callable must be).
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/control/MetricExpression.h"
#include "mesher/control/PerThreadState.h"
#include "mesher/geometry/ParametricSurface.h"

namespace aniso {

class CSAnalytic2d final : public ControlSpace2d {
 public:
  using MetricFunction = std::function<Metric2d(const Vec2& uv)>;

  /// Throws InputError for an empty or non-finite domain, an empty f0, or a gMin that is
  /// not finite and ≥ 0.
  CSAnalytic2d(const Box2& domain, MetricFunction f0, SurfacePtr surface = nullptr, double gMin = 0);
  /// Convenience: f_0 = MetricExpression2d(alpha, h1, h2) (InputError for a bad expression).
  CSAnalytic2d(const Box2& domain, const std::string& alpha, const std::string& h1, const std::string& h2,
               SurfacePtr surface = nullptr, double gMin = 0);

  /// A sub-domain function f_i (later ones take precedence).
  void addRegion(const Box2& region, MetricFunction f);

  SurfaceMetricAt getMetric(const Vec2& uv) const override;
  Box2 bounds() const override { return domain_; }

 private:
  Box2 domain_;
  MetricFunction f0_;
  std::vector<std::pair<Box2, MetricFunction>> regions_;
  SurfacePtr surface_;
  double gMin_;
  std::shared_ptr<PerThreadState<ParametricSurface>> surfaces_;
};

}  // namespace aniso
