#include "mesher/adapt/AdaptModel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "mesher/core/Log.h"
#include "mesher/pipeline/Pipeline.h"

namespace aniso {
namespace {

std::string count(double n) { return std::to_string(static_cast<long long>(std::llround(n))); }

std::string ratio(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

/// One mesh with the field's metric scaled to `vertices` (0: to request.error).
std::pair<MeshResult, AdaptSourcesRecord> meshOnce(const Model& model, const PatchMesh& from, const FieldHessians& field,
                                                   const AdaptRequest& request, double vertices) {
  MeshRequest r = request.mesh;
  const AdaptSourcesRecord rec =
      addAdaptSources(model, from, field, {request.norm, vertices, request.error}, r.options, r.user);
  return {meshModel(model, r), rec};
}

}  // namespace

bool AdaptResult::reached() const {
  return stop == "error asked" || stop == "within tolerance";
}

std::size_t outputNodes(const MeshResult& r) {
  return r.volumeRan ? r.volume.mesh.nodes().size() : r.surface.mesh.nodes.size();
}

AdaptResult adaptModel(const Model& model, const PatchMesh& from, const FieldHessians& field, const AdaptRequest& request) {
  AdaptResult out;
  if (request.error > 0) {
    std::tie(out.mesh, out.metric) = meshOnce(model, from, field, request, 0);
    out.rounds.push_back({0, static_cast<double>(outputNodes(out.mesh)), false});
    out.stop = "error asked";
    return out;
  }
  const double asked = request.targetNodes;
  if (!(asked > 0)) throw InputError("adapt: the node count asked must be positive");
  auto miss = [asked](const AdaptRound& r) { return std::abs(std::log(r.made / asked)); };
  double scaled = request.mesh.options.order == 2 ? asked / kQuadraticNodesPerVertex[from.dim] : asked;
  for (;;) {
    auto [mesh, rec] = meshOnce(model, from, field, request, scaled);
    const bool keep = out.rounds.empty() || !mesh.meshed();
    AdaptRound r{scaled, static_cast<double>(outputNodes(mesh)), false};
    // limited: the metric could not reach `scaled`; its prediction lies on the side of the
    // count made when the metric is already as coarse (or as fine) as it can be
    r.limitedAway = rec.limited && (r.made - asked) * (rec.predictedNodes - scaled) > 0;
    out.rounds.push_back(r);
    const bool better = keep || miss(r) < miss(out.rounds[out.kept]);
    if (better) {
      out.mesh = std::move(mesh);
      out.metric = rec;
      out.kept = out.rounds.size() - 1;
    }
    if (!out.mesh.meshed() || !(r.made > 0)) {
      out.stop = "no mesh";
      return out;
    }
    if (std::abs(r.made / asked - 1) <= kCountTolerance) {
      out.stop = "within tolerance";
      break;
    }
    double slope = 1;
    if (out.rounds.size() > 1) {
      const AdaptRound& q = out.rounds[out.rounds.size() - 2];
      slope = std::log(r.made / q.made) / std::log(r.scaled / q.scaled);
      if (!(slope >= kCountSlope[0])) {
        out.stop = "count bound by the model";
        logWarning("adapt: " + count(r.made) + " nodes for " + count(asked) + " asked: the count hardly follows the metric (" +
                   count(q.made) + " then " + count(r.made) + " nodes for a metric scaled " + ratio(r.scaled / q.scaled) +
                   " times): the model bounds it (thin walls, hmin / hmax, curvature)");
        break;
      }
    }
    if (r.limitedAway) {
      out.stop = "metric at hmin / hmax";
      logWarning("adapt: " + count(r.made) + " nodes for " + count(asked) +
                 " asked: the metric is already at its bound (hmin / hmax) on that side");
      break;
    }
    if (static_cast<int>(out.rounds.size()) == kMaxCountRounds) {
      out.stop = "rounds";
      logWarning("adapt: " + count(r.made) + " nodes for " + count(asked) + " asked after " +
                 std::to_string(kMaxCountRounds) + " meshes (tolerance " + count(100 * kCountTolerance) + " %)");
      break;
    }
    logInfo("adapt: " + count(r.made) + " nodes for " + count(asked) + " asked: meshing again with the metric rescaled");
    if (out.firstNodes == 0) out.firstNodes = r.made;
    scaled *= std::pow(asked / r.made, 1 / std::min(slope, kCountSlope[1]));
  }
  if (out.kept + 1 != out.rounds.size())
    logInfo("adapt: kept the closest of the " + std::to_string(out.rounds.size()) + " meshes (" +
            count(out.rounds[out.kept].made) + " nodes)");
  return out;
}

}  // namespace aniso
