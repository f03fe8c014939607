#include "mesher/model/EdgeNormals.h"

#include "mesher/model/EdgePoint.h"

#include <algorithm>
#include <vector>

#include <Eigen/Geometry>

namespace aniso {

std::optional<Vec3> faceNormalAtEdgeMiddle(const Model& model, const ModelEdge& e, int f) {
  const ModelFace& face = model.faces[static_cast<std::size_t>(f)];
  if (!face.surface) return std::nullopt;
  for (const PCurve& pc : e.pcurves)
    if (pc.face == f && pc.curve) {
      const Vec3 n = face.surface->normal(pc.curve->point(0.5 * (e.t0 + e.t1)));
      return face.reversed ? Vec3(-n) : n;
    }
  return std::nullopt;
}

bool isFilmRim(const Model& model, int f) {
  struct Side {
    Vec3 normal, middle;
    double length = 0;
  };
  std::vector<Side> sides;  // per neighbour across an edge: its unit normal there, the edge's middle and length
  for (const Loop& loop : model.faces[static_cast<std::size_t>(f)].loops)
    for (const EdgeUse& u : loop.uses) {
      const ModelEdge& e = model.edges[static_cast<std::size_t>(u.edge)];
      if (e.degenerate) continue;
      const double tm = 0.5 * (e.t0 + e.t1);
      const Vec3 a = edgePoint(model, u.edge, e.t0), m = edgePoint(model, u.edge, tm), b = edgePoint(model, u.edge, e.t1);
      const double length = (m - a).norm() + (b - m).norm();
      for (const int g : e.faces) {
        if (g == f) continue;
        if (const std::optional<Vec3> n = faceNormalAtEdgeMiddle(model, e, g); n && n->norm() > 0)
          sides.push_back({n->normalized(), m, length});
      }
    }
  // two sides facing each other across f (their middles much closer than they are long)
  // whose faces face opposite ways
  for (std::size_t i = 0; i < sides.size(); ++i)
    for (std::size_t j = i + 1; j < sides.size(); ++j)
      if (sides[i].normal.dot(sides[j].normal) < -kOpposedNormalCos &&
          (sides[i].middle - sides[j].middle).norm() < kFacingRatio * std::min(sides[i].length, sides[j].length))
        return true;
  return false;
}

}  // namespace aniso
