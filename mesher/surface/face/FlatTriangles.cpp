#include "mesher/surface/face/FlatTriangles.h"

#include <algorithm>

#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/surface/face/RingCentroidMove.h"

namespace aniso::face {

using del2d::TriId;
using del2d::VertexId;

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
  return !SurfaceLift::collapsed(a, b, c) && chordMeanRatio(a, b, c) < kFlatMeanRatio;
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
        if ((v.index < fixed.size() && fixed[v.index]) || !moveToRingCentroid(tri, lift, v, true, ring)) continue;
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
