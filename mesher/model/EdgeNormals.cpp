#include "mesher/model/EdgeNormals.h"

#include "mesher/model/EdgePoint.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

namespace aniso {

namespace {

/// The normal of face f at the middle of edge e, oriented by `reversed` (ModelFace::reversed
/// or a shell's FaceUse::reversed).
std::optional<Vec3> normalAtEdgeMiddle(const Model& model, const ModelEdge& e, int f, bool reversed) {
  const ModelFace& face = model.faces[static_cast<std::size_t>(f)];
  if (!face.surface) return std::nullopt;
  for (const PCurve& pc : e.pcurves)
    if (pc.face == f && pc.curve) {
      const Vec3 n = face.surface->normal(pc.curve->point(0.5 * (e.t0 + e.t1)));
      return reversed ? Vec3(-n) : n;
    }
  return std::nullopt;
}

/// isFilmRim with the neighbours oriented by `orientation` (face -> reversed; a face not in
/// it keeps ModelFace::reversed).
bool isFilmRimIn(const Model& model, int f, const std::vector<std::pair<int, bool>>& orientation) {
  const auto reversedOf = [&](int g) {
    const auto it = std::lower_bound(orientation.begin(), orientation.end(), std::pair<int, bool>{g, false});
    return it != orientation.end() && it->first == g ? it->second : model.faces[static_cast<std::size_t>(g)].reversed;
  };
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
        if (const std::optional<Vec3> n = normalAtEdgeMiddle(model, e, g, reversedOf(g)); n && n->norm() > 0)
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

}  // namespace

std::optional<Vec3> faceNormalAtEdgeMiddle(const Model& model, const ModelEdge& e, int f) {
  return normalAtEdgeMiddle(model, e, f, model.faces[static_cast<std::size_t>(f)].reversed);
}

std::vector<std::uint8_t> filmRims(const Model& model) {
  // the neighbours as each shell holding a face orients them (a face two solids share is
  // outward of one of them only)
  std::vector<std::vector<std::pair<int, bool>>> orientation(model.shells.size());
  std::vector<std::vector<int>> shellsOf(model.faces.size());
  for (std::size_t s = 0; s < model.shells.size(); ++s) {
    for (const FaceUse& u : model.shells[s].faces) {
      orientation[s].push_back({u.face, u.reversed});
      if (u.face >= 0 && static_cast<std::size_t>(u.face) < shellsOf.size())
        shellsOf[static_cast<std::size_t>(u.face)].push_back(static_cast<int>(s));
    }
    std::sort(orientation[s].begin(), orientation[s].end());
  }
  std::vector<std::uint8_t> rim(model.faces.size(), 0);
  for (int f = 0; f < static_cast<int>(model.faces.size()); ++f) {
    const std::vector<int>& shells = shellsOf[static_cast<std::size_t>(f)];
    bool r = shells.empty() && isFilmRimIn(model, f, {});
    for (std::size_t k = 0; k < shells.size() && !r; ++k)
      r = isFilmRimIn(model, f, orientation[static_cast<std::size_t>(shells[k])]);
    rim[static_cast<std::size_t>(f)] = r ? 1 : 0;
  }
  return rim;
}

}  // namespace aniso
