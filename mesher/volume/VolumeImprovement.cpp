#include "mesher/volume/VolumeImprovement.h"

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "mesher/core/Log.h"

#include "mesher/delaunay3d/SpatialSort.h"
#include "mesher/volume/improve/QualityFlips.h"
#include "mesher/volume/improve/SliverRemoval.h"
#include "mesher/volume/improve/TetScores.h"
#include "mesher/volume/improve/VertexTets.h"
#include "mesher/volume/improve/VertexMover.h"

namespace aniso {

namespace {
/// Floor of the smoothing acceptance (VertexMover::smooth): stars whose worst η_M is
/// below it must raise their worst; others keep it and their mean.
constexpr double kSmoothingQualityFloor = 0.3;

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
/// The smoothing sweeps of one pass: the free vertices in Hilbert order (neighbouring stars
/// are visited one after another; the vertex numbering follows the refinement, scattered
/// over the solid). Smoothing moves vertices only: the stars are read from one incidence
/// snapshot. Returns the number of accepted moves.
std::size_t smoothVertices(const SolidTetMesh& s, improve3d::VertexMover& mover, const VolumeImproveOptions& o) {
  std::vector<std::uint32_t> free;
  std::vector<Vec3> at;
  for (std::uint32_t v = 0; v < s.mesh.numVertices(); ++v)
    if (!s.isFixed(del3d::VertexId(v)) && s.mesh.vertexTet(del3d::VertexId(v)).valid()) {
      free.push_back(v);
      at.push_back(s.mesh.point(del3d::VertexId(v)));
    }
  const std::vector<std::uint32_t> order = del3d::hilbertOrder(at);
  const improve3d::VertexTets incidence(s.mesh);
  mover.setIncidence(&incidence);
  std::size_t moved = 0;
  for (int sweep = 0; sweep < o.smoothingSweeps; ++sweep)
    for (const std::uint32_t i : order)
      if (mover.smooth(del3d::VertexId(free[i]), o.lowGradation, kSmoothingQualityFloor, o.ascentSmoothing)) ++moved;
  mover.setIncidence(nullptr);
  return moved;
}

}  // namespace

VolumeImproveStats improveVolume(SolidTetMesh& s, const ControlSpace3d& cs, const VolumeImproveOptions& o,
                                 improve3d::VertexMetrics* metrics) {
  VolumeImproveStats st;
  s.node.resize(s.mesh.numVertices(), -1);
  std::optional<improve3d::VertexMetrics> own;
  if (!metrics) metrics = &own.emplace(s.mesh, cs);
  improve3d::VertexMetrics& vm = *metrics;
  vm.sync();
  improve3d::VertexMover mover(s, vm);
  std::optional<improve3d::TetScores> scores;  // exact after each pass: the sliver scan reads it
  for (int pass = 0; pass < std::max(o.passes, o.maxPasses); ++pass) {
    if (pass >= o.passes &&
        improve3d::sampledMeanEta(s.mesh, [&](del3d::TetId t) { return (*scores)[t]; }) >= o.passTarget)
      break;
    checkCancel(o.cancel, "volume improvement");
    ++st.passes;
    auto t0 = Clock::now();
    // every tet measured once; smoothing and flips read and keep this cache
    scores.emplace(s.mesh, vm);
    mover.setScores(&*scores);
    st.moved += smoothVertices(s, mover, o);
    st.smoothingSeconds += since(t0);
    t0 = Clock::now();
    mover.setScores(nullptr);
    checkCancel(o.cancel, "volume improvement");
    improve3d::QualityFlips flips(s, vm, o.flipGain, &*scores);
    flips.run(o.flipCandidate);
    st.flips23 += flips.counts().f23;
    st.flips32 += flips.counts().f32;
    st.flips44 += flips.counts().f44;
    st.flipSeconds += since(t0);
    if (o.vertexRemoval) {
      checkCancel(o.cancel, "volume improvement");
      t0 = Clock::now();
      improve3d::VertexRemoval removal(s, vm, &*scores);
      std::vector<del3d::TetId> created, more;
      const improve3d::VertexRemovalStats rs = removal.run(o.removal, created);
      st.removed += rs.removed;
      logDebug("vertex removal: " + std::to_string(rs.candidates) + " candidates, " + std::to_string(rs.removed) +
               " removed (" + std::to_string(rs.byCollapse) + " collapses, " + std::to_string(rs.byDelaunay) +
               " Delaunay fills, " + std::to_string(rs.byGroup) + " groups)");
      for (const del3d::TetId t : created)
        if (s.mesh.isAlive(t)) flips.visit(t, more);
      st.removalSeconds += since(t0);
    }
  }
  checkCancel(o.cancel, "sliver removal");
  const auto t0 = Clock::now();
  if (o.sliverRounds > 0) {
    const improve3d::SliverStats ss = improve3d::removeSlivers(s, cs, vm, o.sliverAngleDeg, o.euclideanSliverAngleDeg,
                                                               o.sliverRounds, o.sliverInsertion,
                                                               scores ? &*scores : nullptr);
    st.sliversBefore = ss.before;
    st.sliversAfter = ss.after;
    st.sliverFlips = ss.flips;
    st.sliverMoves = ss.moves;
    st.sliverInsertions = ss.insertions;
    st.sliverEdgeRemovals = ss.edgeRemovals;
    st.sliverSteinerPoints = ss.steinerPoints;
    st.sliverMetricRounds = ss.metricRounds;
  } else {
    st.sliversBefore = st.sliversAfter = improve3d::countSlivers(s, vm, o.sliverAngleDeg, o.euclideanSliverAngleDeg);
  }
  vm.sync();
  st.sliverSeconds = since(t0);
  logDebug("volume improvement: smoothing " + std::to_string(st.smoothingSeconds) + " s (" + std::to_string(st.moved) +
           " moves), flips " + std::to_string(st.flipSeconds) + " s (" +
           std::to_string(st.flips23 + st.flips32 + st.flips44) + "), vertex removal " +
           std::to_string(st.removalSeconds) + " s (" + std::to_string(st.removed) + "), slivers " +
           std::to_string(st.sliverSeconds) +
           " s (" + std::to_string(st.sliversBefore) + " -> " + std::to_string(st.sliversAfter) + ")");
  return st;
}

}  // namespace aniso
