#pragma once
// transferField — a field of an old mesh at new points (`anisomesh adapt --transfer`, issue
// 19: restarting a transient run on the adapted mesh): each point is located in the old
// mesh (CellLocator.h) and the field interpolated linearly (P1, on the cell's corners) at
// the closest point of the closest cell — inside the old mesh the P1 interpolant itself; a
// new boundary node outside the old facets (the CAD surface, up to their chordal error away)
// takes the value at its foot on them.
#include <vector>

#include "mesher/adapt/PatchMesh.h"

namespace aniso {

struct TransferredField {
  std::vector<double> values;  ///< node-major, `components` per point
  std::size_t outside = 0;     ///< points outside every old cell
  double maxDistance = 0;      ///< the largest distance from such a point to the old mesh
};

/// `values` holds `components` values per old node (node-major). Throws MeshingError for a
/// size mismatch or an old mesh without cells.
TransferredField transferField(const PatchMesh& old, const std::vector<double>& values, int components,
                               const std::vector<Vec3>& points);

}  // namespace aniso
