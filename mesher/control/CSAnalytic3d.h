#pragma once
// CSAnalytic3d — a volume control space whose metric is given by functions (sec. 6.3.2):
// a global function f_0 and optional functions f_i over axis-aligned sub-boxes (the last
// added box containing x decides), evaluated directly. A function is any callable
// x → Metric3d; a MetricExpression3d (h1, h2, h3 and optional directions in x, y, z) is
// one. Points outside bounds() are moved to the nearest point of bounds() first.
// Thread safety: getMetric() is safe concurrently provided the functions are (a
// MetricExpression3d is; a user callable must be).
#include <functional>
#include <utility>
#include <vector>

#include "mesher/control/ControlSpace3d.h"
#include "mesher/control/MetricExpression.h"

namespace aniso {

class CSAnalytic3d final : public ControlSpace3d {
 public:
  using MetricFunction = std::function<Metric3d(const Vec3& x)>;

  /// Throws InputError for an empty or non-finite domain or an empty f0.
  CSAnalytic3d(const Box3& domain, MetricFunction f0);
  /// A sub-domain function f_i (later ones take precedence).
  void addRegion(const Box3& region, MetricFunction f);

  Metric3d getMetric(const Vec3& x) const override;
  Box3 bounds() const override { return domain_; }

 private:
  Box3 domain_;
  MetricFunction f0_;
  std::vector<std::pair<Box3, MetricFunction>> regions_;
};

}  // namespace aniso
