#include "mesher/surface/improve/ImproveFace.h"

#include <cmath>

#include "mesher/core/Error.h"
#include "mesher/surface/improve/GeometricSwap.h"
#include "mesher/surface/improve/LaplaceSmoothing.h"
#include "mesher/surface/improve/Postprocess.h"
#include "mesher/surface/improve/TopologicalSwap.h"
#include "mesher/surface/improve/VertexMetricCache.h"

namespace aniso {

ImproveStats improveFaceMesh(del2d::Triangulation2d& tri, const ControlSpace2d& cs,
                             const std::vector<std::uint8_t>& fixed, const ImproveOptions& options) {
  if (options.passes < 0 || options.smoothingIterations < 0 || !std::isfinite(options.lowGradation) ||
      !(options.swapAngleTolerance >= 0) || !std::isfinite(options.swapAngleTolerance) ||
      !std::isfinite(options.badQuality) || !(options.smoothingQualityFloor <= 1))
    throw MeshingError("improveFaceMesh: invalid options");
  if (fixed.size() < tri.numVertices())
    throw MeshingError("improveFaceMesh: fewer fixed flags than vertices");
  ImproveStats st;
  improve::VertexMetricCache metrics;
  metrics.setLift(options.lift);
  improve::SmoothingOptions smoothing;
  smoothing.iterations = options.smoothingIterations;
  smoothing.lowGradation = options.lowGradation;
  smoothing.qualityFloor = options.smoothingQualityFloor;
  smoothing.metricSize = options.smoothingMetricSize;
  improve::TopologicalSwapOptions topological;
  topological.lowGradation = options.lowGradation;
  topological.angleTolerance = options.swapAngleTolerance;
  improve::GeometricSwapOptions geometric;
  geometric.angleTolerance = options.swapAngleTolerance;

  for (int pass = 0; pass < options.passes; ++pass) {  // alg. 4.2
    checkCancel(options.cancel, "surface improvement");
    metrics.update(tri, cs, fixed);
    const improve::SmoothingStats s = improve::laplaceSmoothing(tri, metrics, smoothing);
    st.moves += s.moved;
    st.rejectedMoves += s.rejected;
    if (options.topologicalSwap) st.topologicalSwaps += improve::topologicalSwap(tri, metrics, topological).flipped;
    if (options.geometricSwap) st.geometricSwaps += improve::geometricSwap(tri, metrics, geometric).flipped;
  }
  if (options.postprocess) {
    metrics.update(tri, cs, fixed);
    improve::PostprocessOptions post;
    post.badQuality = options.badQuality;
    const improve::PostprocessStats p = improve::postprocess(tri, metrics, post);
    st.postprocessFlips = p.flips;
    st.postprocessMoves = p.moves;
    st.badBefore = p.badBefore;
    st.badAfter = p.badAfter;
  }
  return st;
}

}  // namespace aniso
