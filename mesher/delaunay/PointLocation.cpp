#include "mesher/delaunay/PointLocation.h"

#include <algorithm>

#include "mesher/delaunay/Workspace2d.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::del2d {
namespace {

/// Classifies p in the closed triangle t from the three edge orientations (all ≥ 0).
LocateResult classify(TriId t, const double o[3], std::size_t steps) {
  LocateResult r;
  r.tri = t;
  r.steps = steps;
  const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
  if (zeros == 0) {
    r.where = Location::Inside;
  } else if (zeros == 1) {
    r.where = Location::OnEdge;
    r.index = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;
  } else {
    // Two edge lines through p: p is their common vertex (the third index).
    r.where = Location::OnVertex;
    r.index = o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2;
  }
  return r;
}

/// Orientations of p against the three edges of t (edge i: (v[i+1], v[i+2])).
void edgeOrientations(const Triangulation2d& tri, TriId t, const double* p, double o[3]) {
  const std::uint32_t* tv = tri.triVertices(t);
  for (int i = 0; i < 3; ++i)
    o[i] = predicates::orient2d(tri.coords(VertexId(tv[kNext[i]])), tri.coords(VertexId(tv[kPrev[i]])), p);
}

LocateResult exhaustive(const Triangulation2d& tri, const double* p, std::size_t steps) {
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!tri.isAlive(t)) continue;
    double o[3];
    edgeOrientations(tri, t, p, o);
    if (o[0] >= 0 && o[1] >= 0 && o[2] >= 0) return classify(t, o, steps + k);
  }
  LocateResult r;
  r.steps = steps + tri.triangleSlots();
  return r;  // Outside, no triangle
}

}  // namespace

TriId seedTriangle(const Triangulation2d& tri, const Vec2& p) {
  const VertexId v = tri.seeds().nearestSample(p, [&](VertexId c) {
    const TriId t = tri.vertexTriangle(c);
    return t.valid() && tri.isAlive(t);
  });
  if (v.valid()) return tri.vertexTriangle(v);
  if (tri.lastTriangle().valid()) return tri.lastTriangle();
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k)
    if (tri.isAlive(TriId(k))) return TriId(k);
  return TriId();
}

LocateResult locate(const Triangulation2d& tri, const Vec2& point, TriId start) {
  if (!start.valid() || !tri.isAlive(start)) start = seedTriangle(tri, point);
  if (!start.valid()) return LocateResult{};
  Workspace2d& ws = tri.workspace();
  const double* p = point.data();
  const std::size_t limit = std::max<std::size_t>(1000, 2 * tri.numTriangles());
  TriId t = start, from;
  for (std::size_t steps = 1; steps <= limit; ++steps) {
    const std::uint32_t* tv = tri.triVertices(t);
    const std::uint32_t* tn = tri.triNeighbours(t);
    const int r = static_cast<int>(ws.nextRandom() % 3u);
    double o[3];
    TriId next;
    bool outside = false;
    for (int k = 0; k < 3; ++k) {
      const int i = (r + k) % 3;
      const TriId u(tn[i]);
      if (from.valid() && u == from) {
        o[i] = 1.0;  // p is strictly beyond the edge just crossed, seen from `from`
        continue;
      }
      o[i] = predicates::orient2d(tri.coords(VertexId(tv[kNext[i]])), tri.coords(VertexId(tv[kPrev[i]])), p);
      if (o[i] < 0) {
        if (!u.valid()) {
          outside = true;
          continue;  // another edge may still lead on (non-convex regions)
        }
        next = u;
        break;
      }
    }
    if (next.valid()) {
      from = t;
      t = next;
      continue;
    }
    if (outside) {
      LocateResult res;
      res.tri = t;
      res.steps = steps;
      return res;
    }
    return classify(t, o, steps);
  }
  return exhaustive(tri, p, limit);
}

}  // namespace aniso::del2d
