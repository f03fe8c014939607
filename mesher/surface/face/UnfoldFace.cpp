#include "mesher/surface/face/UnfoldFace.h"

#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/Workspace2d.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/surface/face/RingCentroidMove.h"

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

/// The cavity of an insertion is the containing triangle alone (a 1-to-3 split).
class NoConflict final : public del2d::ConflictTest {
 public:
  bool inConflict(const del2d::Triangulation2d&, TriId) const override { return false; }
};

bool ccw(const Vec2& a, const Vec2& b, const Vec2& c) { return predicates::orient2d(a.data(), b.data(), c.data()) > 0; }

/// Split-and-flip for a folded t = (a, b, c) across its unconstrained edge (b, c) with the
/// neighbour u = (c, b, d): a point q inside u, then the flip of (b, c), leaves (a, b, q),
/// (a, q, c), (b, d, q), (d, c, q). Removes a sliver of three rim nodes whose flip alone
/// would fold (the rim is convex in (u, v) but not on the surface). Checked first: all
/// four counter-clockwise and upright; q tried between the edge's middle and d.
bool trySplitAndFlip(del2d::Triangulation2d& tri, const SurfaceLift& lift, TriId t) {
  static const NoConflict kNoConflict;
  for (int i = 0; i < 3; ++i) {
    const TriId u = tri.neighbour(t, i);
    if (!u.valid() || tri.isConstrained(t, i)) continue;
    const int j = tri.neighbourIndex(u, t);
    if (j < 0) continue;
    const VertexId a = tri.vertex(t, i), b = tri.vertex(t, del2d::kNext[i]), c = tri.vertex(t, del2d::kPrev[i]);
    const VertexId d = tri.vertex(u, j);
    const Vec2 &pa = tri.point(a), &pb = tri.point(b), &pc = tri.point(c), &pd = tri.point(d);
    const LiftedPoint &la = lift.at(tri, a), &lb = lift.at(tri, b), &lc = lift.at(tri, c), &ld = lift.at(tri, d);
    for (const double s : {0.5, 0.3, 0.7, 0.15}) {
      const Vec2 q = (1 - s) * 0.5 * (pb + pc) + s * pd;
      if (!ccw(pa, pb, q) || !ccw(pa, q, pc) || !ccw(pb, pd, q) || !ccw(pd, pc, q)) continue;
      const LiftedPoint lq = lift.lift(q);
      if (!SurfaceLift::upright(la, lb, lq) || !SurfaceLift::upright(la, lq, lc) ||
          !SurfaceLift::upright(lb, ld, lq) || !SurfaceLift::upright(ld, lc, lq))
        continue;
      const del2d::InsertPlan plan = del2d::planInsertion(tri, q, kNoConflict, u);
      if (plan.status != del2d::InsertStatus::Inserted || tri.workspace().cavity.size() != 1 ||
          tri.workspace().cavity.front() != u)
        continue;
      const del2d::InsertResult r = del2d::applyInsertion(tri, plan);
      lift.remember(r.vertex, lq);
      TriId e;
      int k = -1;
      if (tri.findEdge(b, c, e, k) || tri.findEdge(c, b, e, k)) {
        const del2d::FlipPlan flip = del2d::canFlip(tri, e, k);
        if (flip.legal) del2d::flip(tri, flip);  // legal: (a, b, q) and (a, q, c) checked above
      }
      return true;
    }
  }
  return false;
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
      bool moved = false;
      for (int i = 0; i < 3 && !moved; ++i) {
        const VertexId v = tri.vertex(t, i);
        moved = !(v.index < fixed.size() && fixed[v.index]) && moveToRingCentroid(tri, lift, v, false, ring);
      }
      if (moved) {
        ++st.moves;
        changed = true;
      } else if (trySplitAndFlip(tri, lift, t)) {
        ++st.splits;
        changed = true;
      }
    }
    folded = notUpright(tri, lift);
    st.foldedAfter = static_cast<int>(folded.size());
    if (!changed) break;
  }
  return st;
}

}  // namespace aniso::face
