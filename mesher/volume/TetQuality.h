#pragma once
// TetQuality — quality measures of the tetrahedra of one solid (thesis sec. 2.5, the
// report's quality block; issue 5 §2 targets):
//   Euclidean (as the referee /work/shared/tools/meshq.py measures them):
//     mean ratio η = 12 (9 V²)^{1/3} / Σ l_ij², signed (MeanRatio.h, identical formula);
//     dihedral angles: for each of the 6 edges, the interior angle between the two faces
//     at it, acos(−n_i·n_j) with n the outward unit face normals, in degrees.
//     meshq.py's "dihedral_min" is not quite this: it builds the normals of faces
//     (b,c,d), (a,c,d), (a,b,d), (a,b,c) as (y−x)×(z−x), two of which point inwards, so
//     it takes the true angle at edges bd and ac and 180° minus the true angle at the four
//     others (a regular tet gives min 70.53°, max 109.47°; a flat sliver ~178°). Its
//     minimum is ≥ θ whenever every true dihedral angle lies in [θ, 180° − θ]:
//     refereeMinDihedral reproduces it exactly (vertex-order dependent).
//   Metric (sec. 2.5.1–2.5.2, table 5.6):
//     η_M per tet (eq. 2.47–2.48) in the mean of its four vertices' tensors and μ_M per
//     unique edge (eq. 2.14, 2.49) in the mean of its two ends' tensors, as the improvement
//     measures them; one control-space query per vertex. (The refinement measures a tet in
//     eq. 2.18's interpolation, the mean of the length tensors — VertexTensors.h; where the
//     size grades the mean of the tensors is finer, so μ_M here is on the low side there.)
// Stateless; accumulators merge across solids / threads (QualityStats::merge).
#include <cstddef>

#include "mesher/control/ControlSpace3d.h"
#include "mesher/core/Types.h"
#include "mesher/metric/QualityStats.h"
#include "mesher/volume/SolidTetMesh.h"
#include "mesher/volume/VolumeControlSpace.h"
#include "mesher/volume/improve/VertexMetrics.h"

namespace aniso {

/// Euclidean mean ratio of (a, b, c, d): 1 for the regular tet, < 0 when inverted.
double tetMeanRatio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

struct DihedralRange {
  double minDeg = 180, maxDeg = 0;
};
/// Smallest and largest dihedral angle of (a, b, c, d) in degrees (meshq's definition;
/// a degenerate tet gives 0 and/or 180).
DihedralRange tetDihedralRange(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// Smallest dihedral angle only.
double tetMinDihedral(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// Smallest dihedral angle of the tet t of `mesh` (of its four corners, as above).
double tetMinDihedral(const del3d::TetMesh& mesh, del3d::TetId t);
/// True when a dihedral angle of (a, b, c, d) has its cosine above cosAbove (an angle
/// below acos(cosAbove)) or below cosBelow (an angle above acos(cosBelow)): the test of
/// tetDihedralRange's angles against thresholds without acos and without normalising the
/// face normals (cosines compared through their squares). Requires cosAbove ≥ 0 ≥ cosBelow
/// (thresholds at most 90°, at least 90°; cosBelow < −1 disables the large-angle test). A
/// face of zero area gives the cosine 0 for its pairs, as tetDihedralRange does. Either sign
/// of the volume.
bool dihedralCosineOutside(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double cosAbove,
                           double cosBelow);
/// meshq.py's per-tet "dihedral" minimum (see above), for comparing with the referee.
double refereeMinDihedral(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

struct TetQualitySummary {
  std::size_t tets = 0;
  std::size_t inverted = 0;  ///< signed volume ≤ 0 (floating point, as the referee)
  double volume = 0;         ///< sum of signed volumes
  QualityStats meanRatio;    ///< Euclidean η per tet
  double minDihedral = 180;  ///< degrees, over all tets
  double maxDihedral = 0;
  std::size_t belowDihedral = 0;    ///< tets with a dihedral angle below kSliverDihedralDeg
  double refereeMinDihedral = 180;  ///< meshq.py's dihedral_min (see above)
  QualityStats etaM;                ///< η_M per tet (only with a control space)
  QualityStats muM;                 ///< μ_M per unique edge (only with a control space)
  /// μ_M per unique edge in the user's metric M (muM is in M_v, VolumeControlSpace.h).
  QualityStats muMUser;

  void merge(const TetQualitySummary& o);
};

/// Dihedral angle (degrees) below which a tet counts in TetQualitySummary::belowDihedral.
inline constexpr double kSliverDihedralDeg = 5.0;

/// Adds the live tets of s (and, with cs, their η_M and the μ_M of their unique edges)
/// to `out`. cs is the metric the tets were made in; with volume (M_v of
/// VolumeControlSpace.h, usually cs itself) muMUser measures the edges in the user's metric
/// (each vertex's tensor times its length factor — with volume = cs lengthFactorFrom of the
/// tensor held, equal to lengthFactorAt to rounding —, the edge in the mean of its ends'),
/// without it muMUser = muM.
/// With `metrics` (the improvement's per-vertex tensors of cs, current for every vertex of
/// s: improveVolume's VertexMetrics) the vertex tensors are read from it instead of being
/// queried again; the result is the same.
void accumulateTetQuality(const SolidTetMesh& s, const ControlSpace3d* cs, TetQualitySummary& out,
                          const VolumeMetricSpace* volume = nullptr,
                          const improve3d::VertexMetrics* metrics = nullptr);

}  // namespace aniso
