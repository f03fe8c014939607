#include "mesher/surface/face/RingCentroidMove.h"

#include <algorithm>

#include "mesher/predicates/Predicates.h"
#include "mesher/surface/improve/VertexMetricCache.h"

namespace aniso::face {

using del2d::VertexId;

bool moveToRingCentroid(del2d::Triangulation2d& tri, const SurfaceLift& lift, VertexId v, bool mustRaiseShape,
                        std::vector<VertexId>& ring) {
  if (!improve::gatherRing(tri, v, ring)) return false;  // on the border
  const std::size_t n = ring.size();
  Vec2 x = Vec2::Zero();
  for (const VertexId w : ring) x += tri.point(w);
  x /= static_cast<double>(n);
  const LiftedPoint lx = lift.lift(x);
  double before = 1, after = 1;
  for (std::size_t k = 0; k < n; ++k) {
    const VertexId b = ring[k], c = ring[k + 1 == n ? 0 : k + 1];
    if (!(predicates::orient2d(x.data(), tri.coords(b), tri.coords(c)) > 0)) return false;
    const LiftedPoint &lb = lift.at(tri, b), &lc = lift.at(tri, c);
    if (!SurfaceLift::upright(lx, lb, lc)) return false;
    if (mustRaiseShape) {
      before = std::min(before, chordMeanRatio(lift.at(tri, v), lb, lc));
      after = std::min(after, chordMeanRatio(lx, lb, lc));
    }
  }
  if (mustRaiseShape && !(after > before)) return false;
  improve::moveVertex(tri, v, x);
  lift.remember(v, lx);
  return true;
}

}  // namespace aniso::face
