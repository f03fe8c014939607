#include "mesher/pipeline/MeshGrade.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "mesher/highorder/CurvedVolume.h"

namespace aniso {
namespace {

std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

EntityRef solidRef(const Model& model, std::size_t s) { return EntityRef::solid(static_cast<int>(s), model.solids[s].name); }

}  // namespace

std::vector<Problem> gradeVolumeMesh(const Model& model, const VolumeMeshResult& volume, bool isotropic) {
  std::vector<Problem> out;
  const std::size_t n = std::min(model.solids.size(), volume.solids.size());
  std::vector<char> mismatched(model.solids.size(), 0);
  bool anyMismatch = false;
  for (std::size_t s = 0; s < n; ++s) {
    const SolidOutcome& o = volume.solids[s];
    if (o.status != SolidOutcome::Status::Ok || o.tets == 0) continue;
    if (o.quality.refereeMinDihedral < kSliverBarDeg)
      out.push_back({solidRef(model, s), Severity::Degraded, "slivers",
                     format("its smallest dihedral angle is %.2f deg (bar: %.0f deg); %.0f tetrahedra are below 5 deg",
                            o.quality.refereeMinDihedral, kSliverBarDeg, static_cast<double>(o.quality.belowDihedral)),
                     "quality"});
    const double cad = model.solids[s].cadVolume;
    if (cad > 0 && std::abs(o.volume - cad) > kVolumeMismatchRel * cad) {
      mismatched[s] = 1;
      anyMismatch = true;
    }
  }
  if (anyMismatch) {  // the straight volume misses the chordal bulge: check the curved one
    const std::vector<double> curved = curvedSolidVolumes(model, volume.mesh, mismatched);
    for (std::size_t s = 0; s < n; ++s) {
      if (!mismatched[s]) continue;
      const double cad = model.solids[s].cadVolume, rel = (curved[s] - cad) / cad;
      if (std::abs(rel) <= kVolumeMismatchRel) continue;
      out.push_back({solidRef(model, s), Severity::Degraded, "volume-mismatch",
                     format("its mesh encloses %.6g, the CAD solid %.6g (%+.1f %%): a face may be missing, or the CAD "
                            "solid intersects itself or states a wrong volume",
                            curved[s], cad, 100 * rel),
                     "quality"});
    }
  }
  const QualityStats& eta = volume.quality.meanRatio;
  if (isotropic && eta.count() > 0 && eta.mean() < kMeanRatioBar)
    out.push_back({EntityRef::model(), Severity::Degraded, "low-quality",
                   format("the tetrahedra's mean ratio averages %.3f (bar: %.2f)", eta.mean(), kMeanRatioBar), "quality"});
  return out;
}

}  // namespace aniso
