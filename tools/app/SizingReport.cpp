#include "tools/app/SizingReport.h"

namespace aniso::app {
namespace {

nlohmann::ordered_json lengths(const EdgeLengthRange& r) {
  return {{"edges", r.edges}, {"min", r.min}, {"mean", r.mean}, {"max", r.max}};
}

}  // namespace

nlohmann::ordered_json sizingReport(const SizingParameters& p, double modelDiagonal, const SurfaceMesh& surface,
                                    const VolumeMesh* volume) {
  nlohmann::ordered_json j;
  j["hmax"] = p.hmaxFor(modelDiagonal);
  j["hmin"] = p.hminFor(modelDiagonal);
  j["curvature"] = p.curvature;
  if (p.curvature) {
    j["curvature_ratio"] = p.curvatureRatio;
    j["elements_per_circle"] = elementsPerCircleForCurvatureRatio(p.curvatureRatio);
  }
  j["surface_edge_length"] = lengths(edgeLengths(surface));
  if (volume) j["volume_edge_length"] = lengths(edgeLengths(*volume));
  return j;
}

}  // namespace aniso::app
