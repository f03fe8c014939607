#include "mesher/surface/improve/GeometricSwap.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/delaunay/EdgeFlip.h"

namespace aniso::improve {
namespace {

using del2d::kNext;
using del2d::kPrev;

/// Marks t and its neighbours for (re)checking.
void markAround(const Triangulation2d& tri, TriId t, std::vector<std::uint8_t>& dirty,
                std::vector<std::uint32_t>& checkedIn) {
  dirty[t.index] = 1, checkedIn[t.index] = 0;
  for (int k = 0; k < 3; ++k) {
    const TriId n = tri.neighbour(t, k);
    if (n.valid()) dirty[n.index] = 1, checkedIn[n.index] = 0;
  }
}

}  // namespace

double oppositeAngleSum(const Mat2& m, const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  // α at a in (a, b, c) and δ at d in (d, b, c) from unnormalised sines and cosines; the
  // sum α + δ ∈ (0, 2π) from one atan2 of sin(α + δ) and cos(α + δ) (common positive factor).
  const Vec2 ab = m * (b - a), ac = m * (c - a), db = m * (b - d), dc = m * (c - d);
  const double cosA = ab.dot(ac), sinA = std::abs(ab.x() * ac.y() - ab.y() * ac.x());
  const double cosD = db.dot(dc), sinD = std::abs(db.x() * dc.y() - db.y() * dc.x());
  const double sum = std::atan2(sinA * cosD + cosA * sinD, cosA * cosD - sinA * sinD);
  return sum < 0 ? sum + 2 * std::numbers::pi : sum;
}

bool violatesSwapCriterion(const Triangulation2d& tri, const VertexMetricCache& metrics, TriId t, int i,
                           double angleTolerance) {
  const TriId u = tri.neighbour(t, i);
  if (!u.valid() || tri.isConstrained(t, i)) return false;
  const int j = tri.neighbourIndex(u, t);
  if (j < 0) return false;
  const VertexId q[4] = {tri.vertex(t, i), tri.vertex(t, kNext[i]), tri.vertex(t, kPrev[i]), tri.vertex(u, j)};
  const Mat2 m = metrics.blend(q, 4);
  if (angleTolerance <= 0) return del2d::violatesInnerAngles(tri, t, i, del2d::PlaneTransform(m));
  return oppositeAngleSum(m, tri.point(q[0]), tri.point(q[1]), tri.point(q[2]), tri.point(q[3])) >
         std::numbers::pi + angleTolerance;
}

GeometricSwapStats geometricSwap(Triangulation2d& tri, const VertexMetricCache& metrics,
                                 const GeometricSwapOptions& options) {
  if (metrics.size() != tri.numVertices())
    throw MeshingError("geometricSwap: the metric cache does not match the triangulation");
  if (!(options.angleTolerance >= 0) || !std::isfinite(options.angleTolerance) ||
      !(options.maxFlipsPerTriangle >= 0))
    throw MeshingError("geometricSwap: invalid options");
  GeometricSwapStats st;
  const std::size_t slots = tri.triangleSlots();
  std::vector<std::uint8_t> dirty(slots, 0);
  for (std::uint32_t ti = 0; ti < slots; ++ti) dirty[ti] = tri.isAlive(TriId(ti));
  // checkedIn[t] = the sweep in which t's edges were last checked with nothing changed
  // around t since (0: not so): an edge is then not checked again from the other side.
  std::vector<std::uint32_t> checkedIn(slots, 0);
  const double budget = options.maxFlipsPerTriangle * static_cast<double>(tri.numTriangles());
  bool changed = true;
  while (changed) {
    changed = false;
    ++st.sweeps;
    for (std::uint32_t ti = 0; ti < slots; ++ti) {
      if (!dirty[ti]) continue;
      dirty[ti] = 0;
      checkedIn[ti] = static_cast<std::uint32_t>(st.sweeps);
      const TriId t(ti);
      for (int i = 0; i < 3; ++i) {
        const TriId u = tri.neighbour(t, i);
        if (!u.valid() || tri.isConstrained(t, i) || metrics.edgeFrozen(tri, t, i)) continue;
        if (u.index < ti && checkedIn[u.index] == static_cast<std::uint32_t>(st.sweeps)) continue;
        ++st.checked;
        if (!violatesSwapCriterion(tri, metrics, t, i, options.angleTolerance)) continue;
        const del2d::FlipPlan plan = del2d::canFlip(tri, t, i);
        if (!plan.legal || !metrics.flipUpright(tri, plan)) continue;
        if (static_cast<double>(st.flipped) >= budget) {
          st.limitReached = true;
          return st;
        }
        del2d::flip(tri, plan);
        ++st.flipped;
        changed = true;
        markAround(tri, plan.t, dirty, checkedIn);
        markAround(tri, plan.u, dirty, checkedIn);
      }
    }
  }
  return st;
}

}  // namespace aniso::improve
