#pragma once
// VolumeMesher — the whole volume meshing process of a model (thesis 3.5.2, ch. 5), after
// the surface mesh and its repair stage (SurfaceRepair.h: caps and sub-tolerance edges
// force flat tetrahedra, a folded surface overlaps itself so no tetrahedralization contains
// it; mesher/pipeline runs the stage, a caller of meshVolumes alone runs it first): for
// every solid, independently,
//   1 its outward boundary mesh, validated closed and oriented (BoundaryMesh.h);
//   2 the Delaunay triangulation of its boundary nodes (BoundaryTriangulation.h, 5.3);
//   3 boundary recovery (BoundaryRecovery.h, 5.4) and removal of the outside
//     (CarveSolid.h) — the SolidTetMesh invariants hold from here on;
//   4 refinement (VolumeRefinement.h, 5.5) and improvement (VolumeImprovement.h, 5.6)
//     in the solid's 3D control space seen as M_v (VolumeControlSpace.h: tetrahedra of
//     edge length kVolumeLengthFactor times the size), then the quality measures
//     (TetQuality.h);
// then the assembly into one VolumeMesh: the surface mesh's nodes first with the same
// indices (surface nodes are never moved, so solids sharing a face share its nodes and
// triangles: conformal assemblies), then the nodes made inside each solid, solid by
// solid, in kernel order (NodeOn::Kind::Solid). Solids run in parallel on `threads`
// threads; each result is stored by solid index and assembled in order, so the output is
// identical for any number of threads.
//
// Boundary entities that recovery leaves missing are split in the surface mesh on the CAD
// geometry (SplitSurfaceEdges.h: the boundary Steiner points of table 5.3, put where every
// solid sharing the face sees them) and the solids using the changed faces are meshed
// again, for at most maxSplitRounds rounds, with the repair stage after each round; the
// given surface is not changed, the result's surface is it with the splits (and their
// repairs) applied. Without stopWhenThin, when the rounds stop with entities still
// missing, the surface and the pieces go back to the round that had the fewest, and each
// solid still missing some is meshed around its holes (CarveAroundHoles.h: the last
// resort, accepted within kHoleVolumeTolerance of its volume; the solid degraded, problem
// "recovery-holes", VolumeMesh::patchFaces).
// After carving, the boundary triangles whose tet reaches across a thin part are found
// (ThinBoundary.h, alg. 3.3's proximity check) and returned; with stopWhenThin such a solid
// stops there (the caller meshes the surface finer and calls again) — also when the
// recovery left entities missing: a thin solid's missing entities are not split — and so
// do the solids touching a thin one (their boundary changes with the finer surface).
// Faces inside a solid (ModelSolid::embedded) are constraints of its tetrahedra like its
// boundary (recovered, kept by refinement and improvement, crossed by carving); at the end
// the two-sided ones (MeshOptions::internalFaces) are split apart (CrackSplit.h).
// A solid that still cannot be meshed (broken boundary mesh, holes the last resort
// refuses) gets no tetrahedra and its problems are reported by CAD id; the others are
// meshed. Throws only
// for errors that stop everything (bad input).
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "mesher/core/MeshOptions.h"
#include "mesher/core/Problem.h"
#include "mesher/model/Model.h"
#include "mesher/sizing/UserSizing.h"
#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/BoundaryRecovery.h"
#include "mesher/volume/CrackSplit.h"
#include "mesher/volume/TetQuality.h"
#include "mesher/volume/ThinBoundary.h"
#include "mesher/volume/VolumeMesh.h"

namespace aniso {

class SolidMeshCache;

struct VolumeMesherInput {
  const Model* model = nullptr;
  const SurfaceMesh* surface = nullptr;
  MeshOptions options;
  const UserSizing* user = nullptr;
  RecoveryOptions recovery;
  bool refine = true;    ///< phase 4 refinement (off: boundary-only tetrahedra)
  bool improve = true;   ///< phase 4 improvement
  bool validate = false; ///< run the validators after every phase (tests); problems fail the solid
  bool quality = true;   ///< measure the tetrahedra (TetQuality.h) for the report
  /// The last resort of recovery (SplitSurfaceEdges.h): boundary edges and triangles left
  /// unrecovered are split in the surface mesh, on the CAD geometry, and the solids using
  /// the changed faces are meshed again; at most this many rounds, only while fewer than
  /// twice the first round's entities are missing, and until maxStalledSplitRounds rounds
  /// in a row leave no fewer missing than the best round (0: off, the solid fails). Each
  /// round meshes only the solids that changed; a curved model needs 7 of them
  /// (docs/measurements.md).
  int maxSplitRounds = 8;
  /// Splitting that stalls does not recover the solid (docs/measurements.md), and each round
  /// meshes the solids again. 0: no such bound.
  int maxStalledSplitRounds = 2;
  /// Alg. 3.3's proximity check (ThinBoundary.h): a solid with thin boundary triangles
  /// after carving, or after a recovery that left entities missing, stops there (no
  /// splits, no refinement, no tetrahedra in the result) and reports
  /// them in VolumeMeshResult::thin, for the caller to mesh the surface finer and call again.
  /// When some solid is thin, the solids sharing a surface node with it stop after carving
  /// too (VolumeMeshResult::solidsDeferred): the finer surface changes their boundary, so
  /// their tetrahedra would be made again; the other solids are meshed to the end.
  bool stopWhenThin = false;
  /// Optional (SolidMeshCache.h): solids whose boundary is unchanged since an earlier call
  /// with this cache take their tetrahedra from it (the result is the same); every solid
  /// meshed to the end is stored in it.
  SolidMeshCache* cache = nullptr;
};

/// Geometric tolerance of the surface sliver mending (SurfaceSlivers.h), times h_min.
inline constexpr double kSurfaceSliverTolerance = 0.1;

/// A solid's problems name the solid, or the face or CAD edge where recovery failed, by
/// 1-based id (mesher/core/Problem.h); severity Failed (the solid has no tetrahedra).
using VolumeProblem = Problem;

struct SolidOutcome {
  enum class Status { Ok, Failed } status = Status::Ok;
  std::vector<VolumeProblem> problems;
  RecoveryStats recovery;
  std::size_t tets = 0;
  std::size_t innerNodes = 0;  ///< nodes created inside the solid
  double volume = 0;           ///< sum of the tetrahedra's volumes
  std::vector<std::pair<std::string, double>> times;  ///< phase -> seconds
  std::vector<std::pair<std::string, double>> counters;  ///< phase statistics (refinement, improvement)
  TetQualitySummary quality;   ///< Euclidean and metric quality of the solid's tetrahedra
  /// Failed only because a face of its boundary has no surface mesh (problem code
  /// "face-unmeshed"): the surface's shortcoming, not the volume mesher's.
  bool leftOutBySurface() const;
};

struct VolumeMeshResult {
  VolumeMesh mesh;
  std::vector<SolidOutcome> solids;
  RecoveryStats recovery;                             ///< summed over the solids
  int boundarySplits = 0;  ///< surface edges split by the last resort of recovery (mesh.surface has them)
  int splitRounds = 0;     ///< rounds of splitting and meshing again
  /// The repair stage after the split rounds (SurfaceRepair.h): folded edges mended,
  /// nodes merged, caps flipped.
  int foldsRepaired = 0;
  int surfaceNodesMerged = 0;
  int surfaceCapsFlipped = 0;
  /// Boundary triangles thinner than their size across the solid (ThinBoundary.h), solid
  /// by solid; with stopWhenThin the solids having some were not meshed further.
  std::vector<ThinSpot> thin;
  TetQualitySummary quality;                          ///< over all solids
  std::vector<std::pair<std::string, double>> times;  ///< phase -> seconds summed over the solids
  CrackSplitStats cracks;  ///< the two-sided embedded faces separated (CrackSplit.h)
  int solidsReused = 0;    ///< solids taken from VolumeMesherInput::cache (not meshed again)
  /// With stopWhenThin: solids recovered and carved, not thin, but stopped there because
  /// they touch a thin solid (no tetrahedra in the result, status Ok).
  int solidsDeferred = 0;
  /// Solids whose recovery left boundary entities out even after the split rounds, meshed
  /// around the holes (CarveAroundHoles.h) with a "recovery-holes" problem: degraded.
  int solidsWithHoles = 0;
  /// Every solid meshed, or left out only because the surface left out one of its faces.
  bool ok() const;
};

VolumeMeshResult meshVolumes(const VolumeMesherInput& in);

}  // namespace aniso
