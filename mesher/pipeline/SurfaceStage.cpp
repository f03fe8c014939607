#include "mesher/pipeline/SurfaceStage.h"

#include "mesher/volume/VolumeMesher.h"

namespace aniso {

SurfaceMeshResult meshRepairedSurface(const SurfaceMesherInput& in, SurfaceRepairStats* repair) {
  SurfaceMeshResult sr = meshSurfaces(in);
  const double tolerance = kSurfaceSliverTolerance * in.options.sizing.hminFor(in.model->diagonal());
  *repair = repairSurface(*in.model, tolerance, sr.mesh);
  return sr;
}

}  // namespace aniso
