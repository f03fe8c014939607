#include "mesher/control/CSAnalytic2d.h"

#include <cmath>
#include <string>

#include "mesher/core/Error.h"

namespace aniso {

CSAnalytic2d::CSAnalytic2d(const Box2& domain, MetricFunction f0, SurfacePtr surface, double gMin)
    : domain_(domain), f0_(std::move(f0)), surface_(std::move(surface)), gMin_(gMin) {
  if (domain.empty() || !domain.lo.allFinite() || !domain.hi.allFinite())
    throw InputError("analytic control space: the domain is empty or not finite");
  if (!f0_) throw InputError("analytic control space: no global metric function");
  if (!(std::isfinite(gMin) && gMin >= 0))
    throw InputError("analytic control space: gMin = " + std::to_string(gMin) + " must be finite and >= 0");
  if (surface_) {
    const ParametricSurface* s = surface_.get();
    surfaces_ = std::make_shared<PerThreadState<ParametricSurface>>([s] { return s->clone(); });
  }
}

CSAnalytic2d::CSAnalytic2d(const Box2& domain, const std::string& alpha, const std::string& h1,
                           const std::string& h2, SurfacePtr surface, double gMin)
    : CSAnalytic2d(domain, MetricExpression2d(alpha, h1, h2), std::move(surface), gMin) {}

void CSAnalytic2d::addRegion(const Box2& region, MetricFunction f) {
  if (region.empty() || !f) throw InputError("analytic control space: empty sub-domain or no function");
  regions_.emplace_back(region, std::move(f));
}

SurfaceMetricAt CSAnalytic2d::getMetric(const Vec2& uv) const {
  const Vec2 p = uv.cwiseMax(domain_.lo).cwiseMin(domain_.hi);
  const MetricFunction* f = &f0_;
  for (auto it = regions_.rbegin(); it != regions_.rend(); ++it)
    if (it->first.contains(p)) {
      f = &it->second;
      break;
    }
  SurfaceMetricAt r;
  r.sizing = (*f)(p);
  if (surfaces_) r.parameterization = surfaces_->local().parameterizationTensor(p, gMin_);
  return r;
}

}  // namespace aniso
