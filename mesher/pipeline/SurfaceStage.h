#pragma once
// The surface stage of meshModel (Pipeline.h), the same for 2D and 3D: the surface mesh
// (SurfaceMesher.h), then the repair stage (mesher/volume/SurfaceRepair.h) within
// kSurfaceSliverTolerance times h_min. Every surface the pipeline makes — the first, a
// proximity round's, the coarse-solid retry's — goes through it.
#include "mesher/surface/SurfaceMesher.h"
#include "mesher/volume/SurfaceRepair.h"

namespace aniso {

/// meshSurfaces(in), repaired; `repair` (not null) receives what the repair did.
SurfaceMeshResult meshRepairedSurface(const SurfaceMesherInput& in, SurfaceRepairStats* repair);

}  // namespace aniso
