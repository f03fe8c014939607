#include "mesher/volume/VolumeImprovement.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "mesher/core/Log.h"
#include "mesher/core/ParallelFor.h"

#include "mesher/delaunay3d/SpatialSort.h"
#include "mesher/volume/improve/QualityFlips.h"
#include "mesher/volume/improve/SliverRemoval.h"
#include "mesher/volume/improve/SmoothingSchedule.h"
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
/// over the solid), in blocks smoothed class after class, the blocks of a class by up to
/// o.threads threads (SmoothingSchedule.h): the same positions for any number of threads.
/// Smoothing moves vertices only: the stars are read from one incidence snapshot. Returns
/// the number of accepted moves.
std::size_t smoothVertices(SolidTetMesh& s, improve3d::VertexMetrics& vm, improve3d::TetScores& scores,
                           const VolumeImproveOptions& o) {
  std::vector<std::uint32_t> free;
  std::vector<Vec3> at;
  for (std::uint32_t v = 0; v < s.mesh.numVertices(); ++v)
    if (!s.isFixed(del3d::VertexId(v)) && s.mesh.vertexTet(del3d::VertexId(v)).valid()) {
      free.push_back(v);
      at.push_back(s.mesh.point(del3d::VertexId(v)));
    }
  std::vector<std::uint32_t> order = del3d::hilbertOrder(at);
  for (std::uint32_t& i : order) i = free[i];
  const improve3d::VertexTets incidence(s.mesh);
  const improve3d::SmoothingSchedule schedule = improve3d::smoothingSchedule(s.mesh, incidence, order);
  const int threads = std::max(1, o.threads);
  std::vector<improve3d::VertexMover> movers;
  movers.reserve(static_cast<std::size_t>(threads));
  for (int t = 0; t < threads; ++t) {
    movers.emplace_back(s, vm);
    movers.back().setScores(&scores);
    movers.back().setIncidence(&incidence);
  }
  std::vector<std::size_t> moved(static_cast<std::size_t>(threads), 0);
  s.mesh.setCertifiedDelaunay(false);  // before the threads: moves then leave the flag alone
  for (int sweep = 0; sweep < o.smoothingSweeps; ++sweep)
    for (std::size_t c = 0; c < schedule.classes(); ++c)
      parallelForOnThreads(schedule.classStart[c], schedule.classStart[c + 1], threads, [&](int t, std::size_t k) {
        const std::uint32_t b = schedule.blocks[k];
        for (std::size_t i = schedule.blockStart[b]; i < schedule.blockStart[b + 1]; ++i)
          if (movers[static_cast<std::size_t>(t)].smooth(del3d::VertexId(schedule.vertices[i]), o.lowGradation,
                                                         kSmoothingQualityFloor, o.ascentSmoothing))
            ++moved[static_cast<std::size_t>(t)];
      });
  std::size_t total = 0;
  for (const std::size_t m : moved) total += m;
  return total;
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
    st.moved += smoothVertices(s, vm, *scores, o);
    st.smoothingSeconds += since(t0);
    t0 = Clock::now();
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
    st.sliverReconnections = ss.reconnections;
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
