#pragma once
// refineVolume — insertion of inner nodes (thesis sec. 5.5, alg. 5.3).
//
// Every live tet K gets q(K) = S_oI / S_oK (eq. 5.2): the volume of the circumsphere of
// the ideal (unit, regular) tet over that of K, both in the metric M_K at K's centroid;
// q = (R_I / R_K)³ with R_I = √6/4. M_K is interpolated from the vertices' tensors by
// eq. 2.18, as the control space interpolates (the inverse of the mean of their length
// tensors: refine/VertexTensors.h tetLengthMetric; one control-space call per vertex, the
// one made for the insertion reused, not one per evaluated tet, which are several per final
// tet: docs/measurements.md; a tet with four isotropic vertices takes a scalar fast path).
// The mean of the tensors themselves is ruled by the finest vertex where the size grades (a
// harmonic mean of the sizes): measured so, the tets next to a fine boundary looked too
// large, and the points inserted for them, each with the coarser metric of its place, ended
// closer than a unit apart (docs/measurements.md).
// When q(K) ≥ q_t but an edge of K is longer than edgeLengthMax in the metric at its
// midpoint (eq. 2.18 of its ends' tensors), q(K) = 0.95 q_t (5.5.1);
// edges joining two surface nodes are not checked (a boundary edge cannot be shortened by
// inner nodes: the check would refine around it without end).
// Tets with q < q_t go into a queue, worst first (refine/RefineQueue.h: a bucket queue, worst
// first to within q_t / 64). The worst K is refined by a point P:
//   MLE (q(K) < q_It): the midpoint of K's longest (in M_K) edge that is not a boundary
//        edge (not on a constrained face);
//   CCS (otherwise, or when every edge of K is a boundary edge): the circumcentre of K in
//        metric space (M_K x), mapped back.
// P is inserted with del3d::Inserter (in-sphere test on M(P)·x, M(P) the metric at P,
// constant during the insertion — on the untransformed points when M(P) is isotropic, which
// gives the same signs exactly; constrained faces are never crossed) with mustRemove = K.
// The Inserter keeps every tet's circumsphere (Inserter::cacheSpheres): the cavity test with
// the identity is a certified distance comparison backed by the exact insphere (which
// decides the few tests it leaves: docs/measurements.md), and q(K) reads R_K from it.
// The insertion is cancelled (the mesh is unchanged) when:
//   - P is outside the solid (the walk from K leaves through a boundary face: thesis
//     "the refined and containing elements may be divided by some boundary face");
//   - P is closer than minVertexDistance, in M(P), to a vertex of its containing tet;
//   - (MLE only) P is closer than minBoundaryDistance, in M(P), to the plane of a boundary
//     face of its containing tet: halving an edge from a node near the boundary would
//     otherwise make ever flatter tets at the boundary, without end (a CCS point is at
//     least the circumradius away from the vertices, and outside for such flat tets);
//   - (CCS in an anisotropic M_K) a vertex of the containing tet, of its neighbours or of
//     theirs lies inside K's circumsphere in M_K (closer to P than kCircumsphereMargin
//     R_K): the triangulation is Delaunay only in the metric of each point at its
//     insertion, not in M_K, so the circumcentre may land next to a vertex (isotropic
//     metrics: the constrained Delaunay triangulation leaves the sphere empty, no test);
//   - the metric at P differs so much from M_K that K would not be in the cavity
//     (Inserter status Pointless, sec. 5.5.2 third rule); or the Inserter refuses.
// A cancelled MLE falls back to CCS; a cancelled CCS does not fall back to MLE (the
// midpoint of the longest edge of a tet whose circumcentre was refused lands 0.2-0.5 in
// the metric from other vertices in anisotropic layers: docs/measurements.md). When no
// point is inserted K is postponed: its q is raised by postponeFactor (thesis: "moved
// further down the heap") and it is retried, at most maxPostpones times, after other
// insertions.
// New vertices are free (node = −1, SolidTetMesh::addFreeVertex semantics); fixed vertices
// and constrained faces are untouched, so validateSolidTetMesh holds afterwards.
// Order: the queue is consumed in batches — the worst queue.size() / batchDivisor entries
// (at most maxBatch) are refined in the Hilbert order of their centroids, entries made
// stale by earlier insertions of the batch skipped. Worst first holds between batches;
// within one, spatial order keeps the walks short and the memory accesses local (the
// strict order jumps across the mesh at every insertion, ever slower per tet as the mesh
// grows: docs/measurements.md).
// Deterministic: no randomness beyond the Inserter's seeded walk.
// Budget: refinement stops (stats.budgetExhausted) once the solid has maxVertices
// vertices, or budgetFactor × max(eq. 6.2 prediction, 10⁵) vertices more than at the start
// (a unit mesh has about 5.5 tets per vertex, so this is an order of magnitude above the
// expected count: a guard against a refinement that would not end, not a size control).
#include <cstddef>
#include <cstdint>
#include <functional>

#include "mesher/core/Cancel.h"
#include "mesher/control/ControlSpace3d.h"
#include "mesher/volume/SolidTetMesh.h"
#include "mesher/volume/refine/VertexTensors.h"

namespace aniso {

struct VolumeRefineProgress {
  std::size_t tets = 0;      ///< current number of tets (NT_c)
  double worstQuality = 0;   ///< q(K_0): of the tet just refined (the refinement front)
  double predictedTets = 0;  ///< eq. 6.1 (NT_c q_t / q(K_0))
};

struct VolumeRefineOptions {
  double qualityThreshold = 0.57;  ///< q_t (sec. 5.5.1)
  double edgeLengthMax = 1.5;      ///< l_M threshold of the edge check (sec. 5.5.1)
  /// q_It: MLE below, CCS at or above (sec. 5.5.2, table 5.5). 0 (pure CCS) gives the best
  /// mean ratio and smallest dihedral angle on isotropic meshes, as the thesis found
  /// (docs/measurements.md).
  double methodSwitch = 0.0;
  double minVertexDistance = 0.4;    ///< cancellation: metric distance to the nearest vertex
  double minBoundaryDistance = 0.3;  ///< cancellation of MLE points: metric distance to the boundary
  double postponeFactor = 1.5;       ///< q raised by this factor when K cannot be refined now
  int maxPostpones = 3;
  std::size_t maxVertices = 100'000'000;  ///< vertex budget of the solid
  double budgetFactor = 2.0;              ///< vertex budget relative to the eq. 6.2 tet count
  std::size_t batchDivisor = 4;           ///< batch = queue size / batchDivisor (see above)
  std::size_t maxBatch = 1 << 16;
  /// Afterwards, renumberSpatially(s, vertices before the refinement).
  bool renumber = true;
  /// Called about every progressInterval insertions (may be empty).
  std::function<void(const VolumeRefineProgress&)> progress;
  std::size_t progressInterval = 10000;
  /// Checked every batch (Cancel.h); null: never stops.
  const CancelToken* cancel = nullptr;
};

struct VolumeRefineStats {
  std::size_t inserted = 0;  ///< new vertices
  std::size_t insertedMLE = 0, insertedCCS = 0;
  std::size_t cancelledOutside = 0, cancelledClose = 0, cancelledMetric = 0, cancelledRefused = 0;
  std::size_t abandoned = 0;  ///< tets left below q_t after maxPostpones attempts
  std::size_t evaluated = 0;  ///< q(K) evaluations
  std::size_t initialTets = 0, finalTets = 0;
  double predictedInitial = 0;  ///< eq. 6.2 at the start
  bool budgetExhausted = false;
};

/// `tensors` (optional): receives the vertex tensors the refinement queried, numbered as the
/// refined mesh (for the improvement, which would query the same metrics again).
VolumeRefineStats refineVolume(SolidTetMesh& s, const ControlSpace3d& cs, const VolumeRefineOptions& o = {},
                               refine3d::VertexTensorTable* tensors = nullptr);

/// Memory locality for the phases after the refinement (TetMesh::renumber): the vertices from
/// firstVertex on are renumbered along a Hilbert curve (those before keep their numbers),
/// `node` follows them, and the tets are renumbered by their highest vertex number (free
/// slots dropped, so tet ids from before are not kept). Deterministic.
/// Returns the vertex map (old id → new id).
std::vector<std::uint32_t> renumberSpatially(SolidTetMesh& s, std::size_t firstVertex);

/// q(K) of eq. 5.2 for the tet (a, b, c, d) in the metric m (without the edge check).
double refinementQuality(const Metric3d& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The rough prediction of the final number of tets, eq. 6.2: Σ_K V_M(K) / V_M(K_I), with
/// V_M(K) = |K| det M_K (M_K the mean of the vertices' tensors, as for q(K): one
/// control-space query per vertex, not one per tet) and V_M(K_I) = 1/(6√2) the volume of
/// the unit regular tet.
double predictTetCount(const SolidTetMesh& s, const ControlSpace3d& cs);

/// The running prediction of eq. 6.1: NT_c q_t / q(K_0) (NT_c when q(K_0) ≥ q_t).
double predictTetCount(std::size_t currentTets, double worstQuality, double qualityThreshold);

}  // namespace aniso
