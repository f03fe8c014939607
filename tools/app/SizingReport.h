#pragma once
// The "sizing" block of the run report: the sizes asked for (h_min, h_max in model units,
// the curvature as ratio and as elements per circle, on or off) beside the edge lengths
// the mesh has, so that a user sees the bounds were kept (README, "Element size").
#include <nlohmann/json.hpp>

#include "mesher/core/MeshOptions.h"
#include "mesher/volume/EdgeLengths.h"

namespace aniso::app {

/// `volume` null for a surface mesh.
nlohmann::ordered_json sizingReport(const SizingParameters& p, double modelDiagonal, const SurfaceMesh& surface,
                                    const VolumeMesh* volume);

}  // namespace aniso::app
