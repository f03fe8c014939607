#pragma once
// SolidPiece — the tetrahedra of one solid as meshSolid makes them, before the assembly of
// the solids into one VolumeMesh (VolumeMesher.h).
#include <array>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/volume/ThinBoundary.h"
#include "mesher/volume/VolumeMesher.h"

namespace aniso {

/// Fixed vertices as surface node ids (>= 0), free ones as -(k + 1) for inner[k].
struct SolidPiece {
  SolidOutcome outcome;
  std::vector<std::array<int, 4>> tets;
  std::vector<Vec3> inner;
  std::vector<std::vector<int>> missing;  ///< surface nodes of the boundary edges/triangles not recovered
  std::vector<ThinSpot> thin;
  /// Hull faces that are no boundary triangle, numbered as `tets` (VolumeMesh::patchFaces).
  std::vector<std::array<int, 3>> patches;
  /// Meshed to the end (refined, improved, measured): not stopped at a thin boundary
  /// (VolumeMesherInput::stopWhenThin) nor by a failure.
  bool complete = false;
};

}  // namespace aniso
