#pragma once
// gradeVolumeMesh — the mesh measured against the bars a FEM user (and the referee,
// ../shared/tools/meshq.py) holds it to, each shortcoming a Degraded problem naming the
// solid and its part (phase "quality"), so that a run is never "ok" with a mesh those bars
// reject:
//   "slivers"         a tetrahedron with a dihedral angle below kSliverBarDeg (the detail
//                     says where the flattest is and the CAD faces its nodes lie on);
//   "low-quality"     the mean ratio averaged over all tetrahedra below kMeanRatioBar (of a
//                     surface mesh's triangles below kTriangleMeanRatioBar, gradeSurfaceMesh)
//                     (isotropic meshes only: an anisotropic mesh is stretched on purpose);
//   "volume-mismatch" the solid's mesh, its boundary bent onto the CAD (CurvedVolume.h),
//                     differs from the CAD kernel's volume (ModelSolid::cadVolume) by more
//                     than kVolumeMismatchRel — a face missing, a self-intersecting CAD
//                     solid, or a CAD volume that is itself wrong.
#include <vector>

#include "mesher/core/Problem.h"
#include "mesher/model/Model.h"
#include "mesher/volume/SurfaceGeometry.h"
#include "mesher/volume/VolumeMesher.h"

namespace aniso {

/// Smallest dihedral angle (degrees) of a usable tetrahedron.
inline constexpr double kSliverBarDeg = 2.0;
/// Smallest mean ratio average of a usable isotropic mesh.
inline constexpr double kMeanRatioBar = 0.80;
/// Largest relative difference between a solid's (curved) mesh volume and its CAD volume.
inline constexpr double kVolumeMismatchRel = 0.01;

/// The surface's geometric shortcomings (SurfaceGeometry.h) as Degraded problems (phase
/// "surface"): "surface-fold" per face whose mesh folds over, "flat-triangles" per face with
/// flat triangles, "surface-open" per solid whose closed shells' mesh has open edges.
std::vector<Problem> gradeSurfaceGeometry(const Model& model, const SurfaceGeometryCheck& check);

/// The problems of volume.mesh (the solids meshed, their quality in volume.solids).
std::vector<Problem> gradeVolumeMesh(const Model& model, const VolumeMeshResult& volume, bool isotropic);

/// Smallest mean ratio average (4√3 area / Σ edge², the referee's) of a usable isotropic
/// triangle mesh.
inline constexpr double kTriangleMeanRatioBar = 0.90;

/// A surface mesh's own quality (a --dim 2 result of triangles only, isotropic): "low-quality"
/// when its triangles' mean ratio averages below kTriangleMeanRatioBar. Empty otherwise.
std::vector<Problem> gradeSurfaceMesh(const SurfaceMesh& mesh, bool isotropic);

}  // namespace aniso
