#pragma once
// Inside a closed triangulated surface or not, by the parity of a ray's crossings: the
// test that does not need the surface to be faces of a tetrahedralization (CarveAroundHoles
// uses it where recovery left boundary triangles out).
//
// The ray from p runs in a fixed direction to a point beyond the surface's box; each
// triangle it crosses counts once. Every decision is a sign of predicates::orient3d. A
// ray through an edge or a vertex of the surface, or a point on the surface, is degenerate:
// the next of kRayDirections directions is tried, and when all are degenerate the answer
// is "unknown". Triangles are found through a uniform grid of the surface's box (about one
// cell per triangle). Deterministic.
#include <array>
#include <optional>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

class RayParity {
 public:
  /// The surface: triangles as indices into `points` (which must outlive the test).
  RayParity(const std::vector<Vec3>& points, std::vector<std::array<int, 3>> triangles);

  /// Odd crossings: true; even: false; every ray degenerate: nullopt.
  std::optional<bool> inside(const Vec3& p) const;

 private:
  std::optional<int> crossings(const Vec3& p, const Vec3& q) const;
  std::array<int, 3> cellOf(const Vec3& p) const;

  const std::vector<Vec3>& points_;
  std::vector<std::array<int, 3>> triangles_;
  Vec3 lo_, cell_;
  std::array<int, 3> n_{1, 1, 1};
  std::vector<std::vector<int>> cells_;
  double reach_ = 1;  ///< a ray this long leaves the box from any point in it
  mutable std::vector<int> stamp_;  ///< per triangle: the last query that tested it
  mutable int query_ = 0;
};

inline constexpr int kRayDirections = 8;

}  // namespace aniso
