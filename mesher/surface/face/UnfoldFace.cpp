#include "mesher/surface/face/UnfoldFace.h"

#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/surface/improve/VertexMetricCache.h"

namespace aniso::face {

using del2d::TriId;
using del2d::VertexId;

std::vector<TriId> notUpright(const del2d::Triangulation2d& tri, const SurfaceLift& lift) {
  std::vector<TriId> out;
  if (!lift.active()) return out;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (tri.isAlive(t) && !lift.upright(tri, t)) out.push_back(t);
  }
  return out;
}

namespace {

bool tryFlip(del2d::Triangulation2d& tri, const SurfaceLift& lift, TriId t) {
  for (int i = 0; i < 3; ++i) {
    const del2d::FlipPlan plan = del2d::canFlip(tri, t, i);
    if (!plan.legal || !lift.flipUpright(tri, plan)) continue;
    del2d::flip(tri, plan);
    return true;
  }
  return false;
}

/// v to the centroid of its ring when the star stays valid and upright.
bool tryMove(del2d::Triangulation2d& tri, const SurfaceLift& lift, VertexId v, std::vector<VertexId>& ring) {
  if (!improve::gatherRing(tri, v, ring)) return false;  // on the border
  Vec2 x = Vec2::Zero();
  for (const VertexId w : ring) x += tri.point(w);
  x /= static_cast<double>(ring.size());
  const LiftedPoint lx = lift.lift(x);
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    const VertexId b = ring[k], c = ring[k + 1 == n ? 0 : k + 1];
    if (!(predicates::orient2d(x.data(), tri.coords(b), tri.coords(c)) > 0)) return false;
    if (!SurfaceLift::upright(lx, lift.at(tri, b), lift.at(tri, c))) return false;
  }
  improve::moveVertex(tri, v, x);
  lift.remember(v, lx);
  return true;
}

}  // namespace

UnfoldFaceStats unfoldFace(del2d::Triangulation2d& tri, const SurfaceLift& lift,
                           const std::vector<std::uint8_t>& fixed, int maxRounds) {
  UnfoldFaceStats st;
  std::vector<TriId> folded = notUpright(tri, lift);
  st.foldedBefore = st.foldedAfter = static_cast<int>(folded.size());
  std::vector<VertexId> ring;
  for (int round = 0; round < maxRounds && !folded.empty(); ++round) {
    bool changed = false;
    for (const TriId t : folded) {
      if (!tri.isAlive(t) || lift.upright(tri, t)) continue;
      if (tryFlip(tri, lift, t)) {
        ++st.flips;
        changed = true;
        continue;
      }
      for (int i = 0; i < 3; ++i) {
        const VertexId v = tri.vertex(t, i);
        if ((v.index < fixed.size() && fixed[v.index]) || !tryMove(tri, lift, v, ring)) continue;
        ++st.moves;
        changed = true;
        break;
      }
    }
    folded = notUpright(tri, lift);
    st.foldedAfter = static_cast<int>(folded.size());
    if (!changed) break;
  }
  return st;
}

}  // namespace aniso::face
