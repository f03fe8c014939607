#include "mesher/volume/RayParity.h"

#include <algorithm>
#include <cmath>

#include "mesher/predicates/Predicates.h"

namespace aniso {

namespace {

/// Directions far from the axes and from each other (no plane of a CAD model is likely to
/// hold one).
const std::array<Vec3, kRayDirections> kDirections = {
    Vec3(1, 0.31376, 0.17193),   Vec3(-0.27711, 1, 0.41372),  Vec3(0.23417, -0.37193, 1),
    Vec3(-1, -0.21577, 0.33719), Vec3(0.41113, 0.29173, -1),  Vec3(-0.33391, -1, -0.27113),
    Vec3(1, -0.43171, -0.19373), Vec3(-0.19717, 0.37731, -1)};

int sign(double x) { return (x > 0) - (x < 0); }

}  // namespace

RayParity::RayParity(const std::vector<Vec3>& points, std::vector<std::array<int, 3>> triangles)
    : points_(points), triangles_(std::move(triangles)) {
  Box3 box;
  for (const auto& t : triangles_)
    for (const int v : t) box.add(points_[static_cast<std::size_t>(v)]);
  lo_ = box.lo;
  const Vec3 size = (box.hi - box.lo).cwiseMax(Vec3::Constant(1e-300));
  reach_ = 2 * size.norm() + 1;
  // about one cell per triangle, cells as cubic as the box allows
  const double volume = size.x() * size.y() * size.z();
  const double target = std::max<double>(1, static_cast<double>(triangles_.size()));
  const double h = volume > 0 ? std::cbrt(volume / target) : size.maxCoeff() / std::cbrt(target);
  for (int k = 0; k < 3; ++k) n_[k] = std::clamp(static_cast<int>(std::ceil(size[k] / h)), 1, 256);
  cell_ = Vec3(size.x() / n_[0], size.y() / n_[1], size.z() / n_[2]);
  cells_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2], {});
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    Box3 tb;
    for (const int v : triangles_[t]) tb.add(points_[static_cast<std::size_t>(v)]);
    const std::array<int, 3> a = cellOf(tb.lo), b = cellOf(tb.hi);
    for (int i = a[0]; i <= b[0]; ++i)
      for (int j = a[1]; j <= b[1]; ++j)
        for (int k = a[2]; k <= b[2]; ++k)
          cells_[(static_cast<std::size_t>(k) * n_[1] + j) * n_[0] + i].push_back(static_cast<int>(t));
  }
  stamp_.assign(triangles_.size(), -1);
}

std::array<int, 3> RayParity::cellOf(const Vec3& p) const {
  std::array<int, 3> c;
  for (int k = 0; k < 3; ++k) c[k] = std::clamp(static_cast<int>(std::floor((p[k] - lo_[k]) / cell_[k])), 0, n_[k] - 1);
  return c;
}

std::optional<int> RayParity::crossings(const Vec3& p, const Vec3& q) const {
  ++query_;
  int count = 0;
  // the cells the segment passes (3D DDA), clipped to the grid
  const Vec3 d = q - p;
  std::array<int, 3> c = cellOf(p), step{};
  Vec3 tMax, tDelta;
  for (int k = 0; k < 3; ++k) {
    step[k] = d[k] > 0 ? 1 : (d[k] < 0 ? -1 : 0);
    if (step[k] == 0) {
      tMax[k] = tDelta[k] = INFINITY;
      continue;
    }
    const double edge = lo_[k] + (c[k] + (step[k] > 0 ? 1 : 0)) * cell_[k];
    tMax[k] = (edge - p[k]) / d[k];
    tDelta[k] = cell_[k] / std::abs(d[k]);
  }
  const double* pp = p.data();
  const double* qq = q.data();
  for (int guard = 0; guard < n_[0] + n_[1] + n_[2] + 3; ++guard) {
    for (const int t : cells_[(static_cast<std::size_t>(c[2]) * n_[1] + c[1]) * n_[0] + c[0]]) {
      if (stamp_[static_cast<std::size_t>(t)] == query_) continue;
      stamp_[static_cast<std::size_t>(t)] = query_;
      const auto& tri = triangles_[static_cast<std::size_t>(t)];
      const double* a = points_[static_cast<std::size_t>(tri[0])].data();
      const double* b = points_[static_cast<std::size_t>(tri[1])].data();
      const double* e = points_[static_cast<std::size_t>(tri[2])].data();
      const int sp = sign(predicates::orient3d(a, b, e, pp)), sq = sign(predicates::orient3d(a, b, e, qq));
      if (sp == sq && sp != 0) continue;  // both on one side of the plane
      const int s0 = sign(predicates::orient3d(pp, qq, a, b)), s1 = sign(predicates::orient3d(pp, qq, b, e)),
                s2 = sign(predicates::orient3d(pp, qq, e, a));
      const bool mixed = (s0 > 0 || s1 > 0 || s2 > 0) && (s0 < 0 || s1 < 0 || s2 < 0);
      if (mixed) continue;  // the line passes beside the triangle
      if (sp == 0 || sq == 0 || s0 == 0 || s1 == 0 || s2 == 0) return std::nullopt;  // an edge, a vertex, the plane
      ++count;
    }
    // the next cell
    int k = tMax[0] < tMax[1] ? (tMax[0] < tMax[2] ? 0 : 2) : (tMax[1] < tMax[2] ? 1 : 2);
    if (tMax[k] > 1) break;
    c[k] += step[k];
    if (c[k] < 0 || c[k] >= n_[k]) break;
    tMax[k] += tDelta[k];
  }
  return count;
}

std::optional<bool> RayParity::inside(const Vec3& p) const {
  for (int k = 0; k < 3; ++k)  // beyond the surface's box: outside
    if (p[k] < lo_[k] || p[k] > lo_[k] + n_[k] * cell_[k]) return false;
  for (const Vec3& dir : kDirections) {
    const Vec3 q = p + reach_ * dir.normalized();
    if (const std::optional<int> n = crossings(p, q)) return (*n % 2) == 1;
  }
  return std::nullopt;
}

}  // namespace aniso
