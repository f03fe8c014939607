#include "mesher/surface/face/FlatTriangles.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/surface/improve/VertexMetricCache.h"

namespace aniso::face {

using del2d::TriId;
using del2d::VertexId;

double chordMeanRatio(const LiftedPoint& a, const LiftedPoint& b, const LiftedPoint& c) {
  const Vec3 ab = b.p - a.p, bc = c.p - b.p, ca = a.p - c.p;
  const double sum = ab.squaredNorm() + bc.squaredNorm() + ca.squaredNorm();
  if (!(sum > 0)) return 0;
  return 2 * std::sqrt(3.0) * ab.cross(-ca).norm() / sum;  // 4√3 A, A = |ab × ac| / 2
}

namespace {

double ratio(const del2d::Triangulation2d& tri, const SurfaceLift& lift, VertexId a, VertexId b, VertexId c) {
  return chordMeanRatio(lift.at(tri, a), lift.at(tri, b), lift.at(tri, c));
}

double ratio(const del2d::Triangulation2d& tri, const SurfaceLift& lift, TriId t) {
  return ratio(tri, lift, tri.vertex(t, 0), tri.vertex(t, 1), tri.vertex(t, 2));
}

/// Flat in 3D and not collapsed at a pole (SurfaceLift's Untested-by-collapse triangles
/// have a zero chord too, but no orientation or shape to mend).
bool flat(const del2d::Triangulation2d& tri, const SurfaceLift& lift, TriId t) {
  const LiftedPoint &a = lift.at(tri, tri.vertex(t, 0)), &b = lift.at(tri, tri.vertex(t, 1)),
                    &c = lift.at(tri, tri.vertex(t, 2));
  const double shortest = std::min({(b.p - a.p).squaredNorm(), (c.p - b.p).squaredNorm(), (a.p - c.p).squaredNorm()});
  const double longest = std::max({(b.p - a.p).squaredNorm(), (c.p - b.p).squaredNorm(), (a.p - c.p).squaredNorm()});
  if (!(shortest > kCollapsedEdge * kCollapsedEdge * longest)) return false;
  return chordMeanRatio(a, b, c) < kFlatMeanRatio;
}

bool tryFlip(del2d::Triangulation2d& tri, const SurfaceLift& lift, TriId t) {
  int best = -1;
  double bestGain = 0;
  for (int i = 0; i < 3; ++i) {
    const del2d::FlipPlan plan = del2d::canFlip(tri, t, i);
    if (!plan.legal || !lift.flipUpright(tri, plan)) continue;
    const double before = std::min(ratio(tri, lift, plan.t), ratio(tri, lift, plan.u));
    const double after = std::min(ratio(tri, lift, plan.a, plan.b, plan.d), ratio(tri, lift, plan.a, plan.d, plan.c));
    if (after - before > bestGain) bestGain = after - before, best = i;
  }
  if (best < 0) return false;
  del2d::flip(tri, del2d::canFlip(tri, t, best));
  return true;
}

bool tryMove(del2d::Triangulation2d& tri, const SurfaceLift& lift, VertexId v, std::vector<VertexId>& ring) {
  if (!improve::gatherRing(tri, v, ring)) return false;
  const std::size_t n = ring.size();
  const LiftedPoint& lv = lift.at(tri, v);
  Vec2 x = Vec2::Zero();
  double before = 1;
  for (std::size_t k = 0; k < n; ++k) {
    x += tri.point(ring[k]);
    before = std::min(before, chordMeanRatio(lv, lift.at(tri, ring[k]), lift.at(tri, ring[k + 1 == n ? 0 : k + 1])));
  }
  x /= static_cast<double>(n);
  const LiftedPoint lx = lift.lift(x);
  double after = 1;
  for (std::size_t k = 0; k < n; ++k) {
    const VertexId b = ring[k], c = ring[k + 1 == n ? 0 : k + 1];
    if (!(predicates::orient2d(x.data(), tri.coords(b), tri.coords(c)) > 0)) return false;
    const LiftedPoint &lb = lift.at(tri, b), &lc = lift.at(tri, c);
    if (!SurfaceLift::upright(lx, lb, lc)) return false;
    after = std::min(after, chordMeanRatio(lx, lb, lc));
  }
  if (!(after > before)) return false;
  improve::moveVertex(tri, v, x);
  lift.remember(v, lx);
  return true;
}

std::vector<TriId> flatTriangles(const del2d::Triangulation2d& tri, const SurfaceLift& lift) {
  std::vector<TriId> out;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (tri.isAlive(t) && flat(tri, lift, t)) out.push_back(t);
  }
  return out;
}

}  // namespace

FlatTriangleStats removeFlatTriangles(del2d::Triangulation2d& tri, const SurfaceLift& lift,
                                      const std::vector<std::uint8_t>& fixed, int maxRounds) {
  FlatTriangleStats st;
  if (!lift.active()) return st;
  std::vector<TriId> list = flatTriangles(tri, lift);
  st.before = st.after = static_cast<int>(list.size());
  std::vector<VertexId> ring;
  for (int round = 0; round < maxRounds && !list.empty(); ++round) {
    bool changed = false;
    for (const TriId t : list) {
      if (!tri.isAlive(t) || !flat(tri, lift, t)) continue;
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
    list = flatTriangles(tri, lift);
    st.after = static_cast<int>(list.size());
    if (!changed) break;
  }
  return st;
}

}  // namespace aniso::face
