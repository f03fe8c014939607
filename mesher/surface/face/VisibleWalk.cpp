#include "mesher/surface/face/VisibleWalk.h"

#include "mesher/predicates/Predicates.h"

namespace aniso::face {

using namespace del2d;

VisibleLocation locateVisible(const Triangulation2d& tri, TriId from, const Vec2& p, std::size_t maxSteps) {
  VisibleLocation res;
  if (!p.allFinite()) return res;
  const std::uint32_t* fv = tri.triVertices(from);
  const Vec2 o = (tri.point(VertexId(fv[0])) + tri.point(VertexId(fv[1])) + tri.point(VertexId(fv[2]))) / 3.0;
  TriId t = from;
  for (std::size_t step = 0; step < maxSteps; ++step) {
    res.steps = step + 1;
    const std::uint32_t* tv = tri.triVertices(t);
    const double* x[3] = {tri.coords(VertexId(tv[0])), tri.coords(VertexId(tv[1])), tri.coords(VertexId(tv[2]))};
    double s[3];
    for (int i = 0; i < 3; ++i) s[i] = predicates::orient2d(x[kNext[i]], x[kPrev[i]], p.data());
    if (s[0] >= 0 && s[1] >= 0 && s[2] >= 0) {
      res.found = true;
      res.tri = t;
      return res;
    }
    // The edge through which the segment o→p leaves t: p beyond it, its first endpoint on
    // the right of o→p and its second on the left.
    int exit = -1;
    for (int i = 0; i < 3 && exit < 0; ++i) {
      if (s[i] >= 0) continue;
      const double r = predicates::orient2d(o.data(), p.data(), x[kNext[i]]);
      const double l = predicates::orient2d(o.data(), p.data(), x[kPrev[i]]);
      if (r <= 0 && l >= 0) exit = i;
    }
    // o rounded outside a flat start triangle: any edge with p beyond it.
    for (int i = 0; i < 3 && exit < 0; ++i)
      if (s[i] < 0) exit = i;
    const TriId u = tri.neighbour(t, exit);
    if (!u.valid() || tri.isConstrained(t, exit)) return res;
    t = u;
  }
  return res;
}

}  // namespace aniso::face
