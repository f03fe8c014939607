#pragma once
// The shape quality of a mesh's elements in space, as the run summary shows it and a
// solver cares for (Euclidean, whatever metric the mesh was made in):
//   {"type": "tetrahedra"|"triangles", "count", "measure": "mean_ratio", "min", "mean",
//    "dihedral_min" (tets) | "angle_min" (triangles), degrees,
//    "histogram": {"lo": 0, "hi": 1, "bins": [kQualityBins counts]},
//    "quads": {"count", "measure": "scaled_jacobian", "min", "mean", "histogram"}}  (quads only)
// Mean ratio: 1 for the regular element, ≤ 0 inverted (mesher/metric/MeanRatio.h); the
// scaled Jacobian of quads is mesher/quad/QuadQuality.h's. Values outside [0, 1] fall in
// the end bins. Linear elements only (the corners of quadratic ones).
#include <nlohmann/json.hpp>

#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/VolumeMesh.h"

namespace aniso::io {

/// Bins of the histograms, equal over [0, 1].
inline constexpr int kQualityBins = 10;

/// The triangles (and quads) of a surface mesh.
nlohmann::ordered_json elementQuality(const SurfaceMesh& mesh);
/// The tetrahedra of a volume mesh.
nlohmann::ordered_json elementQuality(const VolumeMesh& mesh);

}  // namespace aniso::io
