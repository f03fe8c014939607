#include "mesher/quad/QuadConversion.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "mesher/core/Log.h"
#include "mesher/quad/PoleTriangles.h"
#include "mesher/quad/SharpCornerTriangles.h"

namespace aniso::quad {
namespace {

void measure(const QuadMesh2d& mesh, VertexMetrics& metrics, QuadStats& st) {
  for (int e = 0; e < mesh.numElements(); ++e) {
    const int n = mesh.sides(e);
    if (n == 0) continue;
    (n == 4 ? st.quads : st.triangles)++;
    if (n == 4) st.jacobian.add(std::max(-1.0, elementQuality(mesh, metrics, mesh.corners[e])));
    for (int k = 0; k < n; ++k) {
      const int f = mesh.adj[e][k];
      if (f != kNone && f < e) continue;  // each edge once
      st.mu.add(metrics.length(mesh.corners[e][k], mesh.corners[e][(k + 1) % n]));
    }
  }
}

}  // namespace

QuadStats convertToQuads(FaceMesh& fm, const ControlSpace2d& cs, const ParametricSurface* surface,
                         std::span<const Vec3> nodes, const QuadOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  QuadStats st;
  QuadMesh2d mesh = QuadMesh2d::fromFaceMesh(fm);
  const std::vector<Corners> poles = detachPoleTriangles(mesh);
  const std::vector<Corners> sharp = detachSharpCornerTriangles(mesh, nodes);
  VertexMetrics metrics(mesh, cs, surface, nodes);
  constexpr const char* kPhase = "quad conversion";
  checkCancel(o.cancel, kPhase);
  st.merge = mergeFront(mesh, metrics, o.merge);
  checkCancel(o.cancel, kPhase);
  auto pairUp = [&] {
    const TransportStats t = pairTriangles(mesh, metrics, o.transport);
    st.paired += t.paired;
    st.moves += t.moves;
    st.failedCuts += t.failedCuts;
    st.failedPairs += t.failedPairs;
  };
  pairUp();
  for (int pass = 0; pass < o.improvementPasses; ++pass) {
    checkCancel(o.cancel, kPhase);
    const TopologyStats t = improveTopology(mesh, metrics, o.topology);
    st.doublets += t.doublets;
    st.collapses += t.collapses;
    st.swaps += t.swaps;
    st.smoothed += smoothQuadMesh(mesh, metrics, o.smooth).moved;
    pairUp();
  }
  if (st.paired > 0) st.smoothed += smoothQuadMesh(mesh, metrics, o.smooth).moved;
  if (o.boundaryPostprocess) st.boundary = postprocessBoundaryLayer(mesh, metrics, o.boundary);
  mesh.compact();
  measure(mesh, metrics, st);
  reattachTriangles(mesh, poles);
  reattachTriangles(mesh, sharp);
  mesh.dropUnusedVertices();
  mesh.toFaceMesh(fm);
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  logDebug("quad conversion: merged " + std::to_string(st.merge.quads) + " (morphed " + std::to_string(st.merge.morphed) +
           ", seams " + std::to_string(st.merge.seams) + ", transition seams " + std::to_string(st.merge.transitionSeams) +
           ", transition splits " + std::to_string(st.merge.transitionSplits) + ", morph failures side/degenerate/shape/top/enclosed/parity " +
           std::to_string(st.merge.morphFailures[1]) + "/" + std::to_string(st.merge.morphFailures[2]) + "/" +
           std::to_string(st.merge.morphFailures[3]) + "/" + std::to_string(st.merge.morphFailures[4]) + "/" +
           std::to_string(st.merge.morphFailures[5]) + "/" + std::to_string(st.merge.morphFailures[6]) + ", odd splits " +
           std::to_string(st.merge.oddSplits) + ", edge splits " + std::to_string(st.merge.edgeSplits) +
           ", forced " + std::to_string(st.merge.forcedOdd) + ", rejected " + std::to_string(st.merge.rejected) + "), left " + std::to_string(st.merge.triangles) +
           ", paired " + std::to_string(st.paired) + " in " + std::to_string(st.moves) + " moves (failed: " + std::to_string(st.failedCuts) + " cuts, " +
           std::to_string(st.failedPairs) + " pairs), swaps " +
           std::to_string(st.swaps) + ", doublets " + std::to_string(st.doublets) + ", collapses " + std::to_string(st.collapses) + ", boundary layer moves " + std::to_string(st.boundary.moved) +
           " (worst " + std::to_string(st.boundary.worstBefore) + " -> " + std::to_string(st.boundary.worstAfter) + ") -> " +
           std::to_string(st.quads) + " quads, " + std::to_string(st.triangles) + " triangles");
  return st;
}

}  // namespace aniso::quad
