#include "mesher/adapt/AdaptSources.h"

#include <cmath>
#include <string>

#include "mesher/adapt/LpMetric.h"
#include "mesher/core/Log.h"
#include "mesher/volume/VolumeControlSpace.h"

namespace aniso {
namespace {

void checkCover(const PatchMesh& p, const Model& model) {
  Box3 box;
  for (std::size_t c = 0; c < p.cellCount(); ++c)
    for (int a = p.offsets[c]; a < p.offsets[c + 1]; ++a) box.add(p.nodes[p.conn[a]]);
  const double tol = kCoverTolerance * model.diagonal();
  const bool covers = ((box.lo - model.bbox.lo).cwiseAbs().array() <= tol).all() &&
                      ((box.hi - model.bbox.hi).cwiseAbs().array() <= tol).all();
  if (!covers)
    throw FieldError("its nodes do not cover the model (their bounding box differs from the model's by more than " +
                     std::to_string(static_cast<int>(std::lround(100 * kCoverTolerance))) +
                     " % of its diagonal): a mesh of another model?");
}

}  // namespace

FieldHessians fieldHessians(const PatchMesh& from, const std::vector<double>& values, HessianMethod method) {
  return {recoverHessian(from, values, method), nodeMeasures(from), nodeNormals(from), boundaryFacets(from)};
}

AdaptSourcesRecord addAdaptSources(const Model& model, const PatchMesh& from, const FieldHessians& field,
                                   const AdaptMetricAsk& ask, const MeshOptions& options, UserSizing& user) {
  checkCover(from, model);
  const SizingParameters& s = options.sizing;
  LpMetricParameters lp;
  lp.dim = from.dim;
  lp.norm = ask.norm;
  lp.error = ask.error;
  lp.targetNodes = ask.error > 0 ? 0 : ask.targetVertices;
  lp.hmin = s.hminFor(model.diagonal());
  lp.hmax = s.hmaxFor(model.diagonal());
  lp.anisotropy = s.anisotropy;
  LpMetric metric;
  try {
    metric = lpMetric(field.hessians, field.measures, field.normals, field.boundary, lp);
  } catch (const MeshingError& e) {
    throw FieldError(e.what());
  }
  if (metric.limited) logWarning("adapt: the asked node count or error is out of reach within [hmin, hmax]");
  const double f = options.dim == 3 ? kVolumeLengthFactor : 1.0;
  std::vector<char> used(from.nodes.size(), 0);
  for (int v : from.conn) used[v] = 1;
  const std::size_t before = user.points.size();
  for (std::size_t i = 0; i < from.nodes.size(); ++i)
    if (used[i]) user.points.push_back({from.nodes[i], Metric3d::fromTensor(metric.metrics[i].tensor() * (f * f))});
  AdaptSourcesRecord r;
  r.sources = user.points.size() - before;
  r.predictedNodes = metric.predictedNodes;
  r.predictedError = metric.predictedError;
  r.limited = metric.limited;
  r.hmin = lp.hmin;
  r.hmax = lp.hmax;
  r.anisotropy = lp.anisotropy;
  r.targetVertices = lp.targetNodes;
  logInfo("adapt: " + std::to_string(r.sources) + " point sources, predicted " +
          std::to_string(static_cast<long long>(std::llround(metric.predictedNodes))) + " nodes");
  return r;
}

}  // namespace aniso
