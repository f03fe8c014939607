#pragma once
// CellLocator — the cell of a PatchMesh closest to a point: the one containing it when one
// does, else the nearest (Euclidean distance to the cell's corner simplex). What
// `adapt --transfer` (FieldTransfer.h) interpolates the old field in: a new boundary node
// lies on the CAD surface, outside the old mesh's facets by up to their chordal error.
//
// The cells' boxes are binned in a uniform grid of about kCellsPerBin cells per bin; a
// query visits rings of bins around the point's until no unvisited bin can hold a closer
// cell. Quadratic cells are located by their corners (straight-sided).
// Read-only after construction: queries are thread-safe. Deterministic: among cells at the
// same distance (a point on a shared facet) the lowest index wins.
#include <array>
#include <vector>

#include "mesher/adapt/PatchMesh.h"

namespace aniso {

/// A barycentric coordinate down to −kInsideTolerance counts as inside (relative: the
/// coordinates are ratios of volumes).
inline constexpr double kInsideTolerance = 1e-12;

struct CellHit {
  int cell = -1;                  ///< −1 only for a mesh without cells
  std::array<double, 4> bary{};   ///< of the closest point of the cell (dim + 1 used), ≥ 0, sum 1
  double distance = 0;            ///< from the point to the cell (0 inside)
};

class CellLocator {
 public:
  explicit CellLocator(const PatchMesh& mesh);
  CellHit locate(const Vec3& x) const;

 private:
  /// The closest point of cell c to x as its barycentric coordinates, and its distance.
  CellHit distanceTo(int c, const Vec3& x) const;
  std::array<int, 3> binOf(const Vec3& x) const;

  const PatchMesh& mesh_;
  Vec3 origin_ = Vec3::Zero();
  double bin_ = 1;
  std::array<int, 3> bins_{1, 1, 1};
  std::vector<int> first_{0};  ///< bin b: cells_[first_[b] .. first_[b+1])
  std::vector<int> cells_;
};

/// Cells per grid bin aimed at.
inline constexpr double kCellsPerBin = 2.0;

}  // namespace aniso
