#include "mesher/control/CSAnalytic3d.h"

#include "mesher/core/Error.h"

namespace aniso {

CSAnalytic3d::CSAnalytic3d(const Box3& domain, MetricFunction f0) : domain_(domain), f0_(std::move(f0)) {
  if (domain.empty() || !domain.lo.allFinite() || !domain.hi.allFinite())
    throw InputError("analytic control space: the domain is empty or not finite");
  if (!f0_) throw InputError("analytic control space: no global metric function");
}

void CSAnalytic3d::addRegion(const Box3& region, MetricFunction f) {
  if (region.empty() || !f) throw InputError("analytic control space: empty sub-domain or no function");
  regions_.emplace_back(region, std::move(f));
}

Metric3d CSAnalytic3d::getMetric(const Vec3& x) const {
  const Vec3 p = x.cwiseMax(domain_.lo).cwiseMin(domain_.hi);
  for (auto it = regions_.rbegin(); it != regions_.rend(); ++it)
    if (it->first.contains(p)) return it->second(p);
  return f0_(p);
}

}  // namespace aniso
