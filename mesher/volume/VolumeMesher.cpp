#include "mesher/volume/VolumeMesher.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <map>
#include <set>
#include <mutex>
#include <optional>
#include <thread>
#include <tuple>

#include <Eigen/Geometry>

#include "mesher/core/Error.h"
#include "mesher/core/Log.h"
#include "mesher/core/ParallelFor.h"
#include "mesher/volume/BoundaryMesh.h"
#include "mesher/volume/BoundaryTriangulation.h"
#include "mesher/volume/CarveAroundHoles.h"
#include "mesher/volume/CarveSolid.h"
#include "mesher/volume/CrackSplit.h"
#include "mesher/volume/SolidMeshCache.h"
#include "mesher/volume/SolidTetMesh.h"
#include "mesher/volume/SplitRounds.h"
#include "mesher/volume/SplitSurfaceEdges.h"
#include "mesher/volume/VolumeControlSpace.h"
#include "mesher/volume/SurfaceRepair.h"
#include "mesher/volume/VolumeImprovement.h"
#include "mesher/volume/VolumeRefinement.h"

namespace aniso {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void fail(SolidPiece& p, const EntityRef& entity, const std::string& what) {
  p.outcome.status = SolidOutcome::Status::Failed;
  p.outcome.problems.push_back({entity, Severity::Failed, "solid-mesh", what, "volume"});
}

std::string solidName(int s) { return "solid " + std::to_string(s + 1); }
EntityRef solidRef(int s) { return EntityRef::solid(s); }

/// The CAD edge (0-based) all the given surface nodes lie on, or -1.
int commonEdge(const SurfaceMesh& surface, const std::vector<int>& nodes) {
  int edge = -1;
  for (const int n : nodes) {
    const NodeOn& on = surface.nodeOn[n];
    if (on.kind != NodeOn::Kind::Edge || (edge >= 0 && on.entity != edge)) return -1;
    edge = on.entity;
  }
  return edge;
}

/// Missing entities grouped by face (or by CAD edge when the entity lies on one): one
/// problem per group with the count and an example.
void reportLeft(SolidPiece& p, int solid, const SurfaceMesh& surface, const std::vector<RecoveryFailure>& left) {
  std::map<std::pair<int, int>, std::pair<int, std::string>> byFace;  // (kind: 0 edge, 1 face; index)
  for (const RecoveryFailure& f : left) {
    const int edge = commonEdge(surface, f.nodes);
    auto& e = byFace[edge >= 0 ? std::make_pair(0, edge) : std::make_pair(1, f.face)];
    if (e.first++ == 0) e.second = f.what;
  }
  for (const auto& [key, e] : byFace)
    fail(p, key.first == 0 ? EntityRef::edge(key.second) : EntityRef::face(key.second),
         std::to_string(e.first) + " boundary edges/triangles not recovered in the tetrahedra of " + solidName(solid) +
             " (e.g. " + e.second + ")");
}

/// The hull faces of s whose three vertices are surface nodes, as sorted node triples.
std::set<std::array<int, 3>> hullNodeTriples(const SolidTetMesh& s) {
  const del3d::TetMesh& m = s.mesh;
  std::set<std::array<int, 3>> out;
  for (std::uint32_t k = 0; k < m.tetSlots(); ++k) {
    const del3d::TetId t(k);
    if (!m.isAlive(t)) continue;
    for (int i = 0; i < 4; ++i) {
      if (m.neighbour(t, i).valid()) continue;
      std::array<int, 3> key;
      for (int j = 0; j < 3; ++j) key[j] = s.node[m.vertex(t, del3d::kFaceVertex[i][j]).index];
      std::sort(key.begin(), key.end());
      if (key[0] >= 0) out.insert(key);
    }
  }
  return out;
}

/// The solid's tets into p; for a solid meshed around holes, with the boundary triangles
/// kept on its hull (`keptTriangles`), its patch faces too.
void extract(const SolidTetMesh& s, SolidPiece& p, const std::vector<std::array<int, 3>>* keptTriangles) {
  const del3d::TetMesh& m = s.mesh;
  std::vector<int> freeIndex(m.numVertices(), 0);
  p.tets.reserve(m.numTets());  // sized once: no doubling at the peak memory of the run
  for (std::uint32_t k = 0; k < m.tetSlots(); ++k) {
    const del3d::TetId t(k);
    if (!m.isAlive(t)) continue;
    std::array<int, 4> q;
    for (int i = 0; i < 4; ++i) {
      const del3d::VertexId v = m.vertex(t, i);
      if (s.node[v.index] >= 0) {
        q[i] = s.node[v.index];
        continue;
      }
      if (freeIndex[v.index] == 0) {
        p.inner.push_back(m.point(v));
        freeIndex[v.index] = static_cast<int>(p.inner.size());
      }
      q[i] = -freeIndex[v.index];
    }
    p.tets.push_back(q);
  }
  if (!s.patchFaces.empty()) {  // a solid meshed around holes: its hull faces that are no boundary triangle
    std::set<std::array<int, 3>> boundary;
    for (const auto& tri : *keptTriangles) {
      std::array<int, 3> k = tri;
      std::sort(k.begin(), k.end());
      boundary.insert(k);
    }
    for (std::uint32_t k = 0; k < m.tetSlots(); ++k) {
      const del3d::TetId t(k);
      if (!m.isAlive(t)) continue;
      for (int i = 0; i < 4; ++i) {
        if (m.neighbour(t, i).valid()) continue;
        std::array<int, 3> f, key;
        for (int j = 0; j < 3; ++j) {
          const std::uint32_t v = m.vertex(t, del3d::kFaceVertex[i][j]).index;
          f[j] = key[j] = s.node[v] >= 0 ? s.node[v] : -freeIndex[v];
        }
        std::sort(key.begin(), key.end());
        if (!boundary.count(key)) p.patches.push_back(f);
      }
    }
  }
  double vol = 0;
  for (std::uint32_t k = 0; k < m.tetSlots(); ++k) {
    const del3d::TetId t(k);
    if (!m.isAlive(t)) continue;
    const Vec3 a = m.point(m.vertex(t, 0));
    vol += (m.point(m.vertex(t, 1)) - a).dot((m.point(m.vertex(t, 2)) - a).cross(m.point(m.vertex(t, 3)) - a)) / 6.0;
  }
  p.outcome.tets = p.tets.size();
  p.outcome.innerNodes = p.inner.size();
  p.outcome.volume = vol;
}

bool validated(SolidPiece& p, const VolumeMesherInput& in, const SolidTetMesh& s, const BoundaryMesh& b,
               const char* phase) {
  if (!in.validate) return true;
  for (const std::string& problem : validateSolidTetMesh(s, b.triangles, b.embedded))
    fail(p, solidRef(s.solid), std::string("after ") + phase + ": " + problem);
  return p.outcome.status == SolidOutcome::Status::Ok;
}

/// The faces of the solid's shells that have no surface mesh: a face the surface mesher
/// left out (its own problem says why), or one the surface repair collapsed (narrower than
/// its tolerance: the boundary stays closed without it).
std::vector<int> unmeshedFaces(const Model& model, const std::vector<std::vector<int>>& faceTriangles, int solid) {
  std::vector<int> out;
  for (const int f : model.solidFaces(solid))
    if (f >= 0 && static_cast<std::size_t>(f) < faceTriangles.size() && faceTriangles[static_cast<std::size_t>(f)].empty())
      out.push_back(f);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// Alg. 3.3's proximity check on the solid's tets as they are (ThinBoundary.h): its thin
/// spots into p.thin; true when it has some.
bool findThin(SolidPiece& p, const BoundaryTriangulation& bt, const Model& model, int solid) {
  p.thin = findThinBoundary(bt.tets, bt.boundary, &model);
  for (ThinSpot& spot : p.thin) spot.solid = solid;
  return !p.thin.empty();
}

/// A solid stopped after carving, its phase 4 still to run (finishSolid); or stopped after
/// a recovery that left entities out (rescueSolid).
struct SolidWork {
  BoundaryMesh b;
  BoundaryTriangulation bt;
  bool selfCrossing = false;  ///< recovery stopped at once: the boundary mesh intersects itself
};

void finishSolid(const VolumeMesherInput& in, const std::vector<std::vector<int>>& faceTriangles, int solid,
                 SolidPiece& p, const BoundaryMesh& b, BoundaryTriangulation& bt, double peelVolume = 0);

/// Phases 1–3 and the thin test of one solid, then (keep null) phase 4. With `keep`, a solid
/// recovered, carved and not thin stops there and its work moves into *keep. With
/// `unrecovered` (and not stopWhenThin), a solid whose recovery left entities out keeps its
/// work there (for rescueSolid, once splitting has stopped).
SolidPiece meshSolid(const VolumeMesherInput& in, const std::vector<std::vector<int>>& faceTriangles, int solid,
                     std::unique_ptr<SolidWork>* keep, std::unique_ptr<SolidWork>* unrecovered) {
  SolidPiece p;
  const CancelToken* cancel = in.options.cancel.get();
  checkCancel(cancel, "volume boundary");
  auto t0 = Clock::now();
  BoundaryMesh b = buildBoundaryMesh(*in.model, *in.surface, faceTriangles, solid);
  const std::vector<std::string> broken = checkBoundaryMesh(b, *in.surface);
  if (const std::vector<int> gone = unmeshedFaces(*in.model, faceTriangles, solid); !gone.empty() && !broken.empty()) {
    std::string list;
    for (std::size_t k = 0; k < gone.size() && k < 5; ++k) list += (k ? ", " : "") + std::to_string(gone[k] + 1);
    if (gone.size() > 5) list += ", ...";
    p.outcome.status = SolidOutcome::Status::Failed;
    p.outcome.problems.push_back({solidRef(solid), Severity::Failed, "face-unmeshed",
                                  "left without tetrahedra: its boundary is open where face" + std::string(gone.size() > 1 ? "s " : " ") +
                                      list + " could not be meshed",
                                  "volume"});
    return p;
  }
  for (const int f : b.internalFaces)
    logWarning(solidName(solid) + ": face " + std::to_string(f + 1) + " lies inside the solid; it is not kept as a boundary");
  p.outcome.times.emplace_back("volume boundary", since(t0));
  for (const std::string& s : broken) fail(p, solidRef(solid), "surface mesh bug: " + s);
  if (!broken.empty()) return p;

  t0 = Clock::now();
  BoundaryTriangulation bt = triangulateBoundary(*in.surface, b);
  p.outcome.times.emplace_back("volume triangulation", since(t0));
  for (const std::string& s : bt.problems) fail(p, solidRef(solid), s);
  if (!bt.problems.empty()) return p;

  t0 = Clock::now();
  checkCancel(cancel, "boundary recovery");
  RecoveryOptions ro = in.recovery;
  ro.cancel = cancel;
  const RecoveryResult rr = recoverBoundary(bt, ro);
  p.outcome.recovery = rr.stats;
  if (!rr.left.empty()) {
    p.outcome.times.emplace_back("volume recovery", since(t0));
    if (in.stopWhenThin) {
      // a solid thin for its triangles gets a finer surface anyway: its missing entities
      // are not split and recovered again (each try of a thin part is costly)
      if (findThin(p, bt, *in.model, solid)) return p;
    }
    reportLeft(p, solid, *in.surface, rr.left);
    for (const RecoveryFailure& f : rr.left) p.missing.push_back(f.nodes);
    if (unrecovered && !in.stopWhenThin)
      *unrecovered = std::make_unique<SolidWork>(SolidWork{std::move(b), std::move(bt), rr.selfCrossing});
    return p;
  }
  p.outcome.times.emplace_back("volume recovery", since(t0));
  t0 = Clock::now();
  const std::vector<std::string> carved = carveSolid(bt.tets, bt.boundary, bt.box);
  p.outcome.times.emplace_back("volume carving", since(t0));
  for (const std::string& s : carved) fail(p, solidRef(solid), s);
  if (!carved.empty() || !validated(p, in, bt.tets, b, "boundary recovery")) return p;
  if (findThin(p, bt, *in.model, solid) && in.stopWhenThin) return p;
  if (keep) {
    *keep = std::make_unique<SolidWork>(SolidWork{std::move(b), std::move(bt)});
    return p;
  }
  finishSolid(in, faceTriangles, solid, p, b, bt);
  return p;
}

/// Phase 4 of a recovered and carved solid: control space, refinement, improvement,
/// quality; then its tetrahedra into p (complete unless a validator fails). A solid meshed
/// around holes has its slivers on the patches peeled off after the improvement, up to
/// `peelVolume` of volume (peelPatchSlivers).
void finishSolid(const VolumeMesherInput& in, const std::vector<std::vector<int>>& faceTriangles, int solid,
                 SolidPiece& p, const BoundaryMesh& b, BoundaryTriangulation& bt, double peelVolume) {
  const CancelToken* cancel = in.options.cancel.get();
  auto t0 = Clock::now();
  std::shared_ptr<VolumeMetricSpace> cs;
  if (in.refine || in.improve || in.quality) {
    checkCancel(cancel, "volume control space");
    t0 = Clock::now();
    // The tetrahedra are made and measured in M_v (VolumeControlSpace.h: M at the surface
    // nodes, edges f·h inside).
    std::vector<Vec3> boundaryNodes;
    boundaryNodes.reserve(b.nodes.size());
    for (const int n : b.nodes) boundaryNodes.push_back(in.surface->nodes[n]);
    std::vector<std::array<int, 3>> constraints = b.triangles;  // the transition layers follow the embedded faces too
    constraints.insert(constraints.end(), b.embedded.begin(), b.embedded.end());
    cs = std::make_shared<VolumeMetricSpace>(
        buildVolumeControlSpace(*in.model, *in.surface, solid, in.options.sizing, in.user, &faceTriangles), boundaryNodes,
        kVolumeLengthFactor,
        std::make_shared<TriangleTree>(in.surface->nodes, constraints,
                                       kVolumeTransitionLayers * in.options.sizing.hmaxFor(in.model->diagonal())));
    p.outcome.times.emplace_back("volume control space", since(t0));
  }
  refine3d::VertexTensorTable tensors;  // the refinement's queried metrics, for the improvement
  if (in.refine && cs) {
    t0 = Clock::now();
    VolumeRefineOptions ro3;
    ro3.cancel = cancel;
    const VolumeRefineStats rs = refineVolume(bt.tets, *cs, ro3, &tensors);
    p.outcome.times.emplace_back("volume refinement", since(t0));
    p.outcome.counters.emplace_back("refinement_inserted", static_cast<double>(rs.inserted));
    p.outcome.counters.emplace_back("refinement_abandoned", static_cast<double>(rs.abandoned));
    if (rs.budgetExhausted)
      p.outcome.problems.push_back({solidRef(solid), Severity::Degraded, "refinement-budget",
                                    "the refinement stopped at its vertex budget (" + std::to_string(rs.finalTets) +
                                        " tetrahedra): elements are larger than the sizing asks somewhere",
                                    "volume"});
    if (!validated(p, in, bt.tets, b, "refinement")) return;
  }
  std::optional<improve3d::VertexMetrics> metrics;  // the improvement's, read by the report
  if (in.improve && cs) {
    t0 = Clock::now();
    VolumeImproveOptions io3;
    io3.cancel = cancel;
    io3.threads = std::max(1, in.options.threads);  // meshVolumes: the threads left to each solid
    const VolumeImproveStats is = improveVolume(bt.tets, *cs, io3, &metrics.emplace(bt.tets.mesh, *cs, tensors));
    p.outcome.times.emplace_back("volume improvement", since(t0));
    p.outcome.counters.emplace_back("improvement_passes", static_cast<double>(is.passes));
    p.outcome.counters.emplace_back("improvement_moved", static_cast<double>(is.moved));
    p.outcome.counters.emplace_back("improvement_flips", static_cast<double>(is.flips23 + is.flips32 + is.flips44));
    p.outcome.counters.emplace_back("improvement_removed", static_cast<double>(is.removed));
    p.outcome.counters.emplace_back("slivers_before", static_cast<double>(is.sliversBefore));
    p.outcome.counters.emplace_back("slivers_after", static_cast<double>(is.sliversAfter));
    p.outcome.counters.emplace_back("sliver_edge_removals", static_cast<double>(is.sliverEdgeRemovals));
    p.outcome.counters.emplace_back("sliver_steiner_points", static_cast<double>(is.sliverSteinerPoints));
    p.outcome.counters.emplace_back("sliver_reconnections", static_cast<double>(is.sliverReconnections));
    if (!validated(p, in, bt.tets, b, "improvement")) return;
  }
  BoundaryMesh peeled;  // b less the boundary triangles peeling took off the hull
  const BoundaryMesh* onHull = &b;
  if (!bt.tets.patchFaces.empty() && peelVolume > 0) {
    const std::size_t n = peelPatchSlivers(bt.tets, kPatchSliverAngle, peelVolume);
    p.outcome.counters.emplace_back("hole_slivers_peeled", static_cast<double>(n));
    if (n > 0) {
      peeled = b;
      peeled.triangles.clear();
      peeled.triangleFace.clear();
      const std::set<std::array<int, 3>> hull = hullNodeTriples(bt.tets);
      for (std::size_t t = 0; t < b.triangles.size(); ++t) {
        std::array<int, 3> key = b.triangles[t];
        std::sort(key.begin(), key.end());
        if (!hull.count(key)) continue;
        peeled.triangles.push_back(b.triangles[t]);
        peeled.triangleFace.push_back(b.triangleFace[t]);
      }
      p.outcome.counters.emplace_back("hole_triangles_peeled",
                                      static_cast<double>(b.triangles.size() - peeled.triangles.size()));
      onHull = &peeled;
    }
    if (!validated(p, in, bt.tets, *onHull, "peeling")) return;
  }
  if (in.quality) {
    t0 = Clock::now();
    accumulateTetQuality(bt.tets, cs.get(), p.outcome.quality, cs.get(), metrics ? &*metrics : nullptr);
    p.outcome.times.emplace_back("volume quality", since(t0));
  }
  extract(bt.tets, p, &onHull->triangles);
  p.complete = true;
}

/// A solid's piece and unrecovered work as a split round left them.
struct SavedPiece {
  SolidPiece piece;
  std::unique_ptr<SolidWork> work;
};

/// The split round with the fewest boundary entities missing over all solids: its surface,
/// the pieces of the solids meshed again since, and the result's split counters then.
struct BestRound {
  std::size_t missing = 0;
  SurfaceMesh surface;
  std::map<int, SavedPiece> saved;
  std::tuple<int, int, int, int, int> counters;
};

/// The last resort for a solid whose recovery left entities out once splitting stopped
/// (CarveAroundHoles.h): carved around the holes and finished, its outcome degraded and
/// naming the faces; when the carving is refused (problems, or a volume off by more than
/// kHoleVolumeTolerance) p stays failed, with a note why.
void rescueSolid(const VolumeMesherInput& in, const std::vector<std::vector<int>>& faceTriangles, int solid,
                 SolidPiece& p, SolidWork& work) {
  auto t0 = Clock::now();
  BoundaryTriangulation& bt = work.bt;
  if (work.selfCrossing) {  // nothing was recovered: all but the crossing entities now
    RecoveryOptions ro = in.recovery;
    ro.cancel = in.options.cancel.get();
    ro.pastSelfCrossings = true;
    const RecoveryResult rr = recoverBoundary(bt, ro);
    p.outcome.recovery = rr.stats;
    p.outcome.times.emplace_back("volume recovery", since(t0));
    t0 = Clock::now();
  }
  const HoleCarving hc = carveAroundHoles(bt.tets, bt.boundary, bt.box);
  const double off = std::abs(hc.keptVolume - hc.enclosedVolume);
  const double allowed = kHoleVolumeTolerance * std::abs(hc.enclosedVolume);
  auto note = [&](const std::string& why) {
    p.outcome.problems.push_back({solidRef(solid), Severity::Note, "holes-refused",
                                  "not meshed around the boundary left out of recovery: " + why, "volume"});
  };
  logDebug(solidName(solid) + ": carving around holes: " + std::to_string(hc.notFound) +
           " boundary triangles not recovered, " + std::to_string(hc.missing.size() - hc.notFound) +
           " lost between the fronts, " + std::to_string(hc.patchFaces) + " patch faces; volume " +
           std::to_string(hc.keptVolume) + " for " + std::to_string(hc.enclosedVolume));
  if (!hc.problems.empty()) return note(hc.problems.front());
  if (!(off <= allowed))
    return note("the tetrahedra would enclose " + std::to_string(hc.keptVolume) + " for a boundary enclosing " +
                std::to_string(hc.enclosedVolume));
  SolidPiece q;
  q.outcome.recovery = p.outcome.recovery;
  q.outcome.times = p.outcome.times;
  q.outcome.times.emplace_back("volume carving", since(t0));
  // the triangles kept on the hull, for the validators (the patch faces are in bt.tets)
  BoundaryMesh kept = work.b;
  std::vector<std::uint8_t> gone(kept.triangles.size(), 0);
  for (const std::size_t t : hc.missing) gone[t] = 1;
  std::map<int, std::pair<int, double>> byFace;  // face -> (triangles, area)
  std::size_t w = 0;
  for (std::size_t t = 0; t < kept.triangles.size(); ++t) {
    if (gone[t]) {
      const auto& tri = kept.triangles[t];
      const Vec3& a = in.surface->nodes[tri[0]];
      auto& e = byFace[kept.triangleFace[t]];
      ++e.first;
      e.second += 0.5 * (in.surface->nodes[tri[1]] - a).cross(in.surface->nodes[tri[2]] - a).norm();
      continue;
    }
    kept.triangles[w] = kept.triangles[t];
    kept.triangleFace[w++] = kept.triangleFace[t];
  }
  kept.triangles.resize(w);
  kept.triangleFace.resize(w);
  if (!validated(q, in, bt.tets, kept, "carving around holes")) {
    p.outcome.problems.insert(p.outcome.problems.end(), q.outcome.problems.begin(), q.outcome.problems.end());
    return;
  }
  for (const auto& [face, e] : byFace) {
    char area[32];
    std::snprintf(area, sizeof area, "%.3g", e.second);
    q.outcome.problems.push_back(
        {EntityRef::face(face), Severity::Degraded, "recovery-holes",
         std::to_string(e.first) + " boundary triangle" + (e.first > 1 ? "s" : "") + " (area " + area +
             ") not faces of the tetrahedra of " + solidName(solid) +
             ": recovery failed there; the volume mesh closes the gap with faces of its own",
         "volume"});
  }
  q.outcome.counters.emplace_back("hole_triangles", static_cast<double>(hc.missing.size()));
  q.outcome.counters.emplace_back("hole_patch_faces", static_cast<double>(hc.patchFaces));
  finishSolid(in, faceTriangles, solid, q, kept, bt, allowed - off);
  if (!q.complete) {
    p.outcome.problems.insert(p.outcome.problems.end(), q.outcome.problems.begin(), q.outcome.problems.end());
    return;
  }
  p = std::move(q);
}

/// Per model face: does one of its triangles have one of the edges?
std::vector<std::uint8_t> facesUsingEdges(const SurfaceMesh& surface, const std::vector<std::array<int, 2>>& edges,
                                          int nf) {
  std::set<std::pair<int, int>> keys;
  for (const auto& e : edges) keys.insert(std::minmax(e[0], e[1]));
  std::vector<std::uint8_t> touched(static_cast<std::size_t>(nf), 0);
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const auto& tr = surface.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (keys.count(std::minmax(tr[k], tr[(k + 1) % 3]))) touched[surface.triangleFace[t]] = 1;
  }
  return touched;
}

/// The solids (in order) whose outer or void shells, or embedded faces, use a touched face.
std::vector<int> solidsUsingFaces(const Model& model, const std::vector<std::uint8_t>& touched) {
  std::vector<int> out;
  for (int s = 0; s < static_cast<int>(model.solids.size()); ++s) {
    std::vector<int> shells = model.solids[s].voidShells;
    shells.push_back(model.solids[s].outerShell);
    bool uses = false;
    for (const int sh : shells)
      if (sh >= 0)
        for (const FaceUse& u : model.shells[sh].faces) uses = uses || touched[u.face];
    for (const EmbeddedFace& e : model.solids[s].embedded) uses = uses || touched[e.face];
    if (uses) out.push_back(s);
  }
  return out;
}

/// Adds times[from..] to the per-phase sums (phases in order of first appearance).
void addTimes(const std::vector<std::pair<std::string, double>>& times, std::size_t from,
              std::map<std::string, double>& sum, std::vector<std::string>& order) {
  for (std::size_t k = from; k < times.size(); ++k) {
    const auto& [phase, sec] = times[k];
    if (!sum.count(phase)) order.push_back(phase);
    sum[phase] += sec;
  }
}

/// With stopWhenThin, when a solid is thin: the solids having a surface node in common with
/// a thin solid (the thin ones too). The finer surface of the next round changes their
/// boundaries, so their phase 4 would be made again; the others (likely unchanged, then
/// taken from the cache) are finished. Empty when no solid is thin.
std::vector<char> solidsNearThin(const Model& model, const SurfaceMesh& surface,
                                 const std::vector<std::vector<int>>& faceTriangles,
                                 const std::vector<SolidPiece>& pieces) {
  const std::size_t ns = pieces.size();
  auto eachNode = [&](std::size_t s, const std::function<bool(int)>& f) {
    for (const int face : model.solidBoundaryFaces(static_cast<int>(s)))
      for (const int t : faceTriangles[static_cast<std::size_t>(face)])
        for (const int n : surface.triangles[static_cast<std::size_t>(t)])
          if (f(n)) return;
  };
  std::vector<char> thinNode(surface.nodes.size(), 0);
  bool any = false;
  for (std::size_t s = 0; s < ns; ++s)
    if (!pieces[s].thin.empty()) {
      any = true;
      eachNode(s, [&thinNode](int n) { return (thinNode[static_cast<std::size_t>(n)] = 1) == 0; });
    }
  if (!any) return {};
  std::vector<char> near(ns, 0);
  for (std::size_t s = 0; s < ns; ++s)
    eachNode(s, [&](int n) { return (near[s] = thinNode[static_cast<std::size_t>(n)]) != 0; });
  return near;
}

/// A split next to a sliver can make caps and fold the surface again (three nearly
/// collinear rim nodes): the surface repair stage (SurfaceRepair.h) once more. Returns the
/// faces whose triangles changed.
std::vector<int> repairAfterSplit(const Model& model, const MeshOptions& options, SurfaceMesh& surface,
                                  int splitNodesFrom, VolumeMeshResult& r) {
  const SurfaceRepairStats s = repairSurface(model, kSurfaceSliverTolerance * options.sizing.hminFor(model.diagonal()),
                                             surface, splitNodesFrom);
  r.surfaceNodesMerged += s.nodesMerged;
  r.surfaceCapsFlipped += s.capsFlipped;
  r.foldsRepaired += s.foldsRepaired;
  return s.facesChanged;
}

/// `in` with options.threads the threads each of `solids` solids meshed at once may use
/// inside it (the improvement's smoothing): all of them for one solid, one each when there
/// are at least as many solids as threads. The mesh does not depend on it.
VolumeMesherInput withThreadsPerSolid(const VolumeMesherInput& in, std::size_t solids) {
  VolumeMesherInput out = in;
  const int threads = in.options.threads > 0 ? in.options.threads
                                             : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  out.options.threads = std::max(1, threads / static_cast<int>(std::clamp<std::size_t>(solids, 1, threads)));
  return out;
}

/// Per solid, its embedded faces that are two-sided under `policy` (none for a solid left
/// without tetrahedra).
std::vector<std::vector<int>> crackFaces(const Model& model, InternalFaces policy,
                                         const std::vector<SolidOutcome>* solids = nullptr) {
  std::vector<std::vector<int>> out(model.solids.size());
  for (std::size_t s = 0; s < model.solids.size(); ++s) {
    if (solids && s < solids->size() && (*solids)[s].status != SolidOutcome::Status::Ok) continue;
    for (const EmbeddedFace& e : model.solids[s].embedded)
      if (policy == InternalFaces::Crack || (policy == InternalFaces::Auto && e.crack)) out[s].push_back(e.face);
  }
  return out;
}

}  // namespace

bool SolidOutcome::leftOutBySurface() const {
  return status == Status::Failed && !problems.empty() &&
         std::all_of(problems.begin(), problems.end(), [](const Problem& p) { return p.code == "face-unmeshed"; });
}

bool VolumeMeshResult::ok() const {
  return std::all_of(solids.begin(), solids.end(),
                     [](const SolidOutcome& s) { return s.status == SolidOutcome::Status::Ok || s.leftOutBySurface(); });
}

VolumeMeshResult meshVolumes(const VolumeMesherInput& input) {
  if (!input.model || !input.surface) throw InputError("meshVolumes: no model or no surface mesh");
  const Model& model = *input.model;
  const int ns = static_cast<int>(model.solids.size());
  const int nf = static_cast<int>(model.faces.size());
  // The surface mesh may get boundary Steiner points (splitSurfaceEdges) between rounds.
  SurfaceMesh surface = *input.surface;
  VolumeMesherInput in = input;
  in.surface = &surface;
  VolumeMeshResult r;
  std::map<std::string, double> timeSum;
  std::vector<std::string> timeOrder;
  std::vector<SolidPiece> pieces(static_cast<std::size_t>(ns));
  std::vector<char> reused(static_cast<std::size_t>(ns), 0);  // taken from in.cache
  // With stopWhenThin, phase 4 waits until every solid's thin test is known (solidsNearThin).
  std::vector<std::unique_ptr<SolidWork>> work(static_cast<std::size_t>(ns));
  // Solids whose recovery left entities out, for rescueSolid once splitting stops.
  std::vector<std::unique_ptr<SolidWork>> unrecovered(static_cast<std::size_t>(ns));
  bool splitStopped = false;  // the split rounds ended with the surface of the last meshing
  std::vector<int> todo(static_cast<std::size_t>(ns));
  for (int s = 0; s < ns; ++s) todo[s] = s;
  // A crack triangle with every node on the crack's front could not open: split first.
  // the splits' nodes stay through the repairs after them (a merge would undo the split)
  const int splitNodesFrom = static_cast<int>(surface.nodes.size());
  if (const auto open = crackEdgesToOpen(model, crackFaces(model, in.options.internalFaces), surface); !open.empty()) {
    splitSurfaceEdges(model, surface, open);
    repairAfterSplit(model, in.options, surface, splitNodesFrom, r);
  }
  SplitRounds rounds(in.maxSplitRounds, in.maxStalledSplitRounds);
  std::optional<BestRound> best;  // for the last resort (not with stopWhenThin)
  for (int round = 0;; ++round) {  // bounded by maxSplitRounds
    checkCancel(in.options.cancel.get(), "volume meshing");
    const std::vector<std::vector<int>> faceTriangles = trianglesByFace(surface, nf);
    if (best)  // the best round's pieces of the solids meshed again, once each
      for (const int s : todo)
        if (!best->saved.count(s)) best->saved.emplace(s, SavedPiece{std::move(pieces[s]), std::move(unrecovered[s])});
    parallelFor(
        static_cast<int>(todo.size()), in.options.threads,
        [&](int i) {
          const int s = todo[i];
          reused[s] = 0;
          work[s].reset();
          unrecovered[s].reset();
          if (in.cache)
            if (std::optional<SolidPiece> hit = in.cache->find(s, solidBoundaryKey(model, surface, faceTriangles, s))) {
              pieces[s] = std::move(*hit);
              reused[s] = 1;
              return;
            }
          pieces[s] = meshSolid(withThreadsPerSolid(in, todo.size()), faceTriangles, s,
                                in.stopWhenThin ? &work[s] : nullptr, &unrecovered[s]);
        },
        "volume");
    for (const int s : todo)
      if (!reused[s]) addTimes(pieces[s].outcome.times, 0, timeSum, timeOrder);
    // Boundary entities no interior point could recover: split them in the surface mesh
    // (an unrecovered triangle by its longest edge) and mesh again every solid using a
    // face that changed, so shared faces stay conformal.
    std::vector<std::array<int, 2>> requests;
    for (const int s : todo)
      for (const std::vector<int>& n : pieces[s].missing) {
        if (n.size() == 2) requests.push_back({n[0], n[1]});
        if (n.size() == 3) requests.push_back(longestEdge(surface, {n[0], n[1], n[2]}));
      }
    // Every round meshes the solids again: stop when splitting diverges or stalls, so a
    // hopeless case does not run on (SplitRounds.h).
    std::size_t missing = 0;
    for (const SolidPiece& p : pieces) missing += p.missing.size();
    if (!in.stopWhenThin && missing > 0 && (!best || missing < best->missing))
      best = BestRound{missing, surface, {}, {r.splitRounds, r.boundarySplits, r.foldsRepaired, r.surfaceNodesMerged,
                                              r.surfaceCapsFlipped}};
    // back to the best round: its surface, the pieces meshed on it
    const auto backToBest = [&] {
      surface = std::move(best->surface);
      for (auto& [s, saved] : best->saved) {
        pieces[s] = std::move(saved.piece);
        unrecovered[s] = std::move(saved.work);
      }
      std::tie(r.splitRounds, r.boundarySplits, r.foldsRepaired, r.surfaceNodesMerged, r.surfaceCapsFlipped) =
          best->counters;
      logDebug("volume: splitting ended with " + std::to_string(missing) + " entities missing; back to the round with " +
               std::to_string(best->missing));
    };
    if (rounds.stop(round, requests.size())) {
      splitStopped = true;
      if (best && best->missing < missing) backToBest();  // splitting ended worse than it was
      break;
    }
    std::vector<std::uint8_t> touched = facesUsingEdges(surface, requests, nf);
    const SplitStats split = splitSurfaceEdges(model, surface, requests);
    for (const int f : repairAfterSplit(model, in.options, surface, splitNodesFrom, r)) touched[f] = 1;
    if (split.edgesSplit == 0) {  // nothing to split: the repair may have changed the surface since
      if (best) {
        splitStopped = true;
        backToBest();
      }
      break;
    }
    ++r.splitRounds;
    r.boundarySplits += split.edgesSplit;
    todo = solidsUsingFaces(model, touched);
    logDebug("volume: " + std::to_string(split.edgesSplit) + " boundary edges split; meshing " +
             std::to_string(todo.size()) + " solids again");
  }

  const std::vector<std::vector<int>> faceTriangles = trianglesByFace(surface, nf);  // the final surface's
  if (splitStopped) {  // the last resort for the solids recovery left entities out of
    std::vector<int> rescue;
    for (int s = 0; s < ns; ++s)
      if (unrecovered[s] && pieces[s].outcome.status == SolidOutcome::Status::Failed) rescue.push_back(s);
    std::vector<std::size_t> timesBefore(static_cast<std::size_t>(ns), 0);  // phases already summed
    for (const int s : rescue) timesBefore[s] = pieces[s].outcome.times.size();
    parallelFor(
        static_cast<int>(rescue.size()), in.options.threads,
        [&](int i) {
          const int s = rescue[i];
          rescueSolid(withThreadsPerSolid(in, rescue.size()), faceTriangles, s, pieces[s], *unrecovered[s]);
          unrecovered[s].reset();
        },
        "volume");
    for (const int s : rescue)
      if (pieces[s].complete) {
        addTimes(pieces[s].outcome.times, timesBefore[s], timeSum, timeOrder);
        ++r.solidsWithHoles;
      }
  }
  unrecovered.clear();
  if (in.stopWhenThin) {  // phase 4 of the solids stopped after carving, unless near a thin one
    const std::vector<char> near = solidsNearThin(model, surface, faceTriangles, pieces);
    std::vector<int> finish;
    std::vector<std::size_t> phasesBefore(static_cast<std::size_t>(ns), 0);  // phase 1–3 times already summed
    for (int s = 0; s < ns; ++s) {
      if (!work[s]) continue;
      if (!near.empty() && near[s]) {
        ++r.solidsDeferred;
        continue;
      }
      finish.push_back(s);
      phasesBefore[s] = pieces[s].outcome.times.size();
    }
    parallelFor(
        static_cast<int>(finish.size()), in.options.threads,
        [&](int i) {
          const int s = finish[i];
          finishSolid(withThreadsPerSolid(in, finish.size()), faceTriangles, s, pieces[s], work[s]->b, work[s]->bt);
          work[s].reset();
        },
        "volume");
    for (const int s : finish) addTimes(pieces[s].outcome.times, phasesBefore[s], timeSum, timeOrder);
    work.clear();
  }
  if (in.cache) {  // the solids meshed by this call, keyed by the surface they were meshed on
    for (int s = 0; s < ns; ++s)
      if (!reused[s]) in.cache->store(s, solidBoundaryKey(model, surface, faceTriangles, s), pieces[s]);
    r.solidsReused = static_cast<int>(std::count(reused.begin(), reused.end(), 1));
  }
  r.mesh.surface = std::move(surface);
  std::size_t totalTets = 0, totalInner = 0;
  for (const SolidPiece& p : pieces) totalTets += p.tets.size(), totalInner += p.inner.size();
  r.mesh.tets.reserve(totalTets);
  r.mesh.tetSolid.reserve(totalTets);
  r.mesh.surface.nodes.reserve(r.mesh.surface.nodes.size() + totalInner);
  r.mesh.surface.nodeOn.reserve(r.mesh.surface.nodes.size() + totalInner);
  for (int s = 0; s < ns; ++s) {
    SolidPiece& p = pieces[s];
    const int base = static_cast<int>(r.mesh.surface.nodes.size());
    for (const Vec3& x : p.inner) {
      NodeOn on;
      on.kind = NodeOn::Kind::Solid;
      on.entity = s;
      r.mesh.surface.addNode(x, on);
    }
    for (const auto& q : p.tets) {
      std::array<int, 4> t;
      for (int i = 0; i < 4; ++i) t[i] = q[i] >= 0 ? q[i] : base - q[i] - 1;
      r.mesh.tets.push_back(t);
      r.mesh.tetSolid.push_back(s);
    }
    for (const auto& q : p.patches) {
      std::array<int, 3> f;
      for (int i = 0; i < 3; ++i) f[i] = q[i] >= 0 ? q[i] : base - q[i] - 1;
      r.mesh.patchFaces.push_back(f);
    }
    r.thin.insert(r.thin.end(), p.thin.begin(), p.thin.end());
    r.recovery.merge(p.outcome.recovery);
    r.quality.merge(p.outcome.quality);
    r.solids.push_back(std::move(p.outcome));
  }
  for (const std::string& phase : timeOrder) r.times.emplace_back(phase, timeSum[phase]);
  r.cracks = splitCracks(model, crackFaces(model, in.options.internalFaces, &r.solids), r.mesh);
  return r;
}

}  // namespace aniso
