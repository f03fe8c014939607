#include "mesher/pipeline/SurfaceStage.h"

#include <chrono>

#include "mesher/volume/VolumeMesher.h"

namespace aniso {

bool surfaceRepairApplies(const SurfaceMesherInput& in, int dim) {
  return dim == 3 || (!in.analytic && in.options.sizing.anisotropy <= 1);
}

SurfaceMeshResult meshRepairedSurface(const SurfaceMesherInput& in, SurfaceRepairStats* repair, bool apply) {
  SurfaceMeshResult sr = meshSurfaces(in);
  *repair = {};
  if (!apply) return sr;
  const double tolerance = kSurfaceSliverTolerance * in.options.sizing.hminFor(in.model->diagonal());
  const auto t0 = std::chrono::steady_clock::now();
  *repair = repairSurface(*in.model, tolerance, sr.mesh);
  sr.times.emplace_back("surface repair", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return sr;
}

}  // namespace aniso
