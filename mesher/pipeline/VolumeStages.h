#pragma once
// The volume stages of meshModel (Pipeline.h, dim 3): alg. 3.3's outer loop made explicit.
//   1 proximity rounds (at most kMaxProximityRounds): the volume with stopWhenThin
//     (VolumeMesher.h); a solid thinner than its boundary triangles (ThinBoundary.h) gets
//     sizing sources on its faces, so does a solid the volume mesher failed on
//     (CoarseSolids.h failedSolidSources), and the whole surface is meshed again (shared
//     edges stay consistent). Sources asking for more than the budget (kMaxProximityGrowth
//     times the first surface, all rounds together) are scaled to fit when the model is
//     thin as a whole (kThinWholeShare); a model thin in places has a smaller budget
//     (kThinInPlacesGrowth, kMaxThinAspect), and the sources of a solid the volume mesher
//     failed on that ask more than the whole budget are scaled to fit that smaller one (a
//     solid without tetrahedra is refined as far as it allows); a solid failing on a finer
//     surface has its refinement undone (UndoRefinement.h); a round is not run when its
//     sources are empty, beyond the budget, or add too little (kMinProximityGrowth); a finer
//     surface that leaves more faces unmeshed is dropped.
//   2 the final volume of the surface kept (no stop when thin);
//   3 fallback: when a finer surface was kept and its volume failed, the volume of the
//     first surface instead (once);
//   4 coarse-solid retry (CoarseSolids.h): the surface once more at a finer size around
//     the solids below the quality bar, kept when the whole mesh's mean ratio is better (a
//     retry that fails, by status or by a MeshingError, leaves the first result).
// Every surface made here goes through the repair stage (SurfaceStage.h). At most 5
// volume meshings and 3 surface meshings. Every decision is appended to
// result.decisions.
#include "mesher/model/Model.h"
#include "mesher/pipeline/MeshResult.h"
#include "mesher/sizing/UserSizing.h"
#include "mesher/pipeline/SurfaceMesher.h"

namespace aniso {

/// Rounds of alg. 3.3's outer loop: the surface meshed again, finer where the solid is
/// thinner than its triangles (ThinBoundary.h), then the volume again.
inline constexpr int kMaxProximityRounds = 2;
/// Budget of the proximity rounds: their sources may ask for at most this many times the
/// first surface mesh's triangles (predictedTriangles), all rounds together; beyond it the
/// sizes are scaled up until the prediction fits (sourcesWithinBudget: refined as far as
/// the budget allows) for a model thin as a whole. A resource guard, not a quality rule: a
/// budget per round compounded, and thin models ask for tens of times the first surface
/// (docs/measurements.md).
inline constexpr double kMaxProximityGrowth = 10.0;
/// A model thin as a whole — at least this share of the surface's triangles thin — gets
/// sources beyond the budget scaled to fit (sourcesWithinBudget); a model thin in places
/// (an assembly's skins and sheets) has the smaller budget below (docs/volume.md).
inline constexpr double kThinWholeShare = 0.5;
/// A model thin in places (not thin as a whole) is refined to the thickness when the
/// surface stays within kThinInPlacesTriangles or kThinInPlacesGrowth times the first
/// surface (and kMaxProximityGrowth), all rounds together; beyond, its sources are scaled
/// up, to at most kMaxThinAspect (elements up to that many times as large as the part is
/// thick: flat tetrahedra across it, about 20 deg at the base edges, but no slivers), to
/// fit kThinInPlacesGrowth times the first surface, and when even that does not fit, the
/// thin solids that fit are refined (cheapestGroupsWithinBudget). A time guard: the volume
/// grows with the surface (about 4 tets per triangle; docs/measurements.md).
inline constexpr double kMaxThinAspect = 8.0;
inline constexpr double kThinInPlacesGrowth = 2.0;
inline constexpr double kThinInPlacesTriangles = 1.6e6;
/// A round whose sources would add less than this share of triangles is not run.
inline constexpr double kMinProximityGrowth = 1.05;

struct VolumeStagesInput {
  const Model* model = nullptr;
  /// How the first surface was made; its `user` is replaced by the stages' finer sizing.
  SurfaceMesherInput surface;
  const UserSizing* user = nullptr;  ///< the user's sizing (the volume's; not null)
  MeshOptions options;
};

/// Runs the stages on result.surface (the first surface mesh) and sets result.surface (the
/// surface kept), result.volume, result.proximity, result.coarse and result.decisions.
void runVolumeStages(const VolumeStagesInput& in, MeshResult& result);

}  // namespace aniso
