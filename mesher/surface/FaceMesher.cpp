#include "mesher/surface/FaceMesher.h"

#include <chrono>
#include <cstdint>
#include <stdexcept>

#include "mesher/core/Error.h"
#include "mesher/surface/face/BoundaryTriangulation.h"
#include "mesher/surface/face/DomainRemoval.h"
#include "mesher/surface/face/EdgeRecovery.h"
#include "mesher/surface/face/FlatTriangles.h"
#include "mesher/surface/face/Refinement.h"
#include "mesher/surface/face/UnfoldFace.h"
#include "mesher/surface/improve/ImproveFace.h"

namespace aniso {

namespace {

using namespace del2d;

/// Boundary vertices first in loop order, then the interior vertices in creation order;
/// triangles in slot order (deterministic).
FaceMesh extractMesh(const Triangulation2d& tri, const face::FlatBoundary& boundary,
                     const std::vector<VertexId>& vertexOf) {
  FaceMesh mesh;
  mesh.uv = boundary.uv;
  mesh.node = boundary.node;
  std::vector<int> out(tri.numVertices(), -1);
  for (std::size_t k = 0; k < boundary.size(); ++k) out[vertexOf[k].index] = static_cast<int>(k);
  for (std::uint32_t v = 0; v < tri.numVertices(); ++v) {
    const VertexId id(v);
    if (out[v] >= 0 || tri.isCorner(id) || !tri.vertexTriangle(id).valid()) continue;
    out[v] = static_cast<int>(mesh.uv.size());
    mesh.uv.push_back(tri.point(id));
    mesh.node.push_back(-1);
  }
  mesh.triangles.reserve(tri.numTriangles());
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!tri.isAlive(t)) continue;
    const std::uint32_t* tv = tri.triVertices(t);
    mesh.triangles.push_back({out[tv[0]], out[tv[1]], out[tv[2]]});
  }
  return mesh;
}

void addProblems(std::vector<std::string>& to, const std::vector<std::string>& from, const std::string& prefix) {
  for (const std::string& p : from) to.push_back(prefix + p);
}

/// Steps 1–5 of FaceMesher.h; fills res (problems on failure).
void runPipeline(const face::FlatBoundary& flat, const ControlSpace2d& cs, const FaceMesherOptions& options,
                 const std::string& prefix, FaceMeshResult& res) {
  // 1: boundary nodes.
  face::BoundaryTriangulation bt = face::triangulateBoundary(flat, cs, options.seed, options.innerAnglesCriterion);
  addProblems(res.problems, bt.problems, prefix);
  if (!res.problems.empty()) return;
  Triangulation2d& tri = bt.tri;
  // 2: boundary edges.
  face::BoundaryRecoveryStats rec;
  addProblems(res.problems, face::recoverBoundaryEdges(tri, flat, bt.vertexOf, cs, &rec), prefix);
  res.stats.missingBoundaryEdges = static_cast<int>(rec.missing);
  if (!res.problems.empty()) return;
  // 3: outside.
  addProblems(res.problems, face::removeOutside(tri, flat, bt.vertexOf), prefix);
  if (!res.problems.empty()) return;
  // 4: inner nodes.
  face::RefineOptions ro;
  ro.qualityThreshold = options.qualityThreshold;
  ro.maxEdgeMetricLength = options.maxEdgeMetricLength;
  ro.mleToCcsQuality = options.mleToCcsQuality;
  ro.innerAngles = options.innerAnglesCriterion;
  ro.onPrediction = options.onPrediction;
  ro.cancel = options.cancel;
  const face::SurfaceLift lift(options.surface);
  ro.lift = &lift;
  // a bridged gap's copies of a vertex are that vertex in 3D (FaceBoundary.h): lifted there,
  // with no normal (as a pole's), so that the fold guard sees the fan the assembly will make
  if (lift.active())
    for (std::size_t k = 0; k < flat.size(); ++k)
      if (flat.at[k].allFinite() && bt.vertexOf[k].valid())
        lift.remember(bt.vertexOf[k], face::LiftedPoint{flat.uv[k], flat.at[k], Vec3::Zero()});
  const face::RefineStats rs = face::refineFace(tri, cs, ro);
  res.stats.insertedInner = static_cast<int>(rs.inserted);
  res.stats.cancelledInsertions = static_cast<int>(rs.cancelled);
  res.stats.predictedTriangles = static_cast<int>(std::min(rs.predictedTriangles, 2e9));
  res.stats.insertionLimitReached = rs.limitReached;
  // 5: improvement; the boundary vertices (and the unused box corners) stay fixed.
  std::vector<std::uint8_t> fixed(tri.numVertices(), 0);
  for (const VertexId v : bt.vertexOf) fixed[v.index] = 1;
  for (const VertexId v : tri.corners()) fixed[v.index] = 1;
  if (options.improvementPasses > 0) {
    ImproveOptions io;
    io.passes = options.improvementPasses;
    io.lift = &lift;
    io.cancel = options.cancel;
    improveFaceMesh(tri, cs, fixed, io);
  }
  checkCancel(options.cancel, "surface improvement");
  // 6: folds the guarded operators could not avoid.
  const face::UnfoldFaceStats uf = face::unfoldFace(tri, lift, fixed);
  res.stats.foldsRepaired = uf.foldedBefore - uf.foldedAfter;
  res.stats.foldsLeft = uf.foldedAfter;
  // 7: caps and needles that are flat on the surface though fine in the metric.
  const face::FlatTriangleStats ft = face::removeFlatTriangles(tri, lift, fixed);
  res.stats.flatTriangles = ft.before;
  res.stats.flatTrianglesLeft = ft.after;
  res.mesh = extractMesh(tri, flat, bt.vertexOf);
}

}  // namespace

FaceMeshResult meshFace(const FaceBoundary& boundary, const ControlSpace2d& cs, const FaceMesherOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  FaceMeshResult res;
  // Problems name no entity: they are the face's own (FaceMeshResult::problems).
  const std::string prefix;
  try {
    const face::FlatBoundary flat = face::flattenBoundary(boundary);  // throws for invalid input
    res.stats.boundaryNodes = static_cast<int>(flat.size());
    runPipeline(flat, cs, options, prefix, res);
  } catch (const Cancelled&) {  // the run stops: not a problem of this face
    throw;
  } catch (const std::runtime_error& e) {  // MeshingError / InputError from the control space or kernel
    res.problems.push_back(prefix + e.what());
  }
  if (!res.problems.empty()) res.mesh = FaceMesh{};
  res.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return res;
}

}  // namespace aniso
