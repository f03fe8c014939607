#pragma once
// The surface stage of meshModel (Pipeline.h), the same for 2D and 3D: the surface mesh
// (SurfaceMesher.h), then the repair stage (mesher/volume/SurfaceRepair.h) within
// kSurfaceSliverTolerance times h_min. Every surface the pipeline makes — the first, a
// proximity round's, the coarse-solid retry's — goes through it.
#include "mesher/pipeline/SurfaceMesher.h"
#include "mesher/volume/SurfaceRepair.h"

namespace aniso {

/// The repair is Euclidean (caps and folds in space, for the volume mesher): it applies to
/// every surface of a 3D run and to isotropic 2D runs; an anisotropic 2D surface (γ_a > 1,
/// or an analytic metric: thesis AN1, whose caps are the metric's intended elements) is
/// the product and keeps its elements.
bool surfaceRepairApplies(const SurfaceMesherInput& in, int dim);

/// meshSurfaces(in), repaired when `apply`; `repair` (not null) receives what the repair did.
SurfaceMeshResult meshRepairedSurface(const SurfaceMesherInput& in, SurfaceRepairStats* repair, bool apply = true);

}  // namespace aniso
