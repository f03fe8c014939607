#pragma once
// The element budget, checked after sizing and before meshing (thesis 6.5; issue 20
// "sizing that cannot explode", issue 18 --max-elements): never a silent hour.
//
// Prediction: the triangles of every face from its control space (FaceSizePrediction.h)
// and, for a volume mesh, the tets of every solid, estimated from the T triangles of its
// shells as kTetsPerTriangle32 · T^{3/2} (see the constant), and when its volume V is known
// no more than kTetsPerVolume · V / h³ (h the mean size on its boundary, h² = A / (√3/4 T),
// A the area of its faces) nor less than T: a thin part has about as many tets as
// boundary triangles, T^{3/2} is a compact part's count. Elements = triangles (+ tets).
// Decision (decideBudget), for a limit N > 0:
//   - predicted ≤ N: nothing changes;
//   - else the smallest floor h_c on every sizing length (h_i ← max(h_i, h_c): the faces
//     that ask for the smallest sizes, which contribute most, are coarsened first) for which
//     the prediction fits, by bisection on log h_c (kFloorBisections steps); the faces whose
//     prediction the floor lowers by more than kCoarsenedShare are reported, the largest
//     reduction first;
//   - when even h_c = h_max does not fit, fits = false: the caller stops with the
//     prediction (InputError, exit 2).
// The default N (defaultElementBudget) is the machine's memory over the bytes one element
// costs while meshing (kBytesPerTriangle, kBytesPerTet).
#include <vector>

#include "mesher/sizing/FaceSizePrediction.h"

namespace aniso {

/// Tets per (boundary triangles)^{3/2} of a solid. A uniform mesh of a cube of side L with
/// size h has 6 L² / (√3/4 h²) = 13.9 L²/h² triangles and L³ / (h³/(6√2)) = 8.5 L³/h³
/// tets: 0.165 T^{3/2}; graded meshes are coarser inside. 0.1: the largest ratio measured on
/// real parts (docs/measurements.md).
inline constexpr double kTetsPerTriangle32 = 0.1;
/// Tets per V / h³ of a solid of volume V with boundary size h: a uniform mesh has 8.5
/// (a regular tet holds h³ / (6√2)); 5.15 is kTetsPerTriangle32's share of the uniform
/// cube's 0.165, so that both estimates agree on compact parts. It bounds thin parts, whose
/// tets T^{3/2} alone predicts many times over, so that the budget's floor does not coarsen
/// their proximity sources (docs/measurements.md).
inline constexpr double kTetsPerVolume = 5.15;
/// Peak resident bytes per element while meshing, the program's own footprint included in
/// the margin: per surface triangle, and per tet while meshing a volume (surface included);
/// a margin above the peak measured per element (docs/measurements.md).
inline constexpr double kBytesPerTriangle = 200.0;
inline constexpr double kBytesPerTet = 150.0;
/// Steps of the bisection for the floor (each halves log(h_max / h_smallest)).
inline constexpr int kFloorBisections = 40;
/// A face counts as coarsened when the floor lowers its prediction by more than this share.
inline constexpr double kCoarsenedShare = 0.01;

struct BudgetCoarsening {
  int face = -1;           ///< 0-based model face
  double before = 0;       ///< its predicted triangles as asked
  double after = 0;        ///< with the floor
};

struct ElementBudget {
  double limit = 0;        ///< N
  double predicted = 0;    ///< elements as the sizing asks (triangles + tets)
  double triangles = 0, tets = 0;  ///< the parts of `predicted`
  bool fits = true;        ///< predicted (with the floor, if any) ≤ N
  double floor = 0;        ///< h_c applied to every face (0: none)
  double predictedAfter = 0;       ///< with the floor
  std::vector<BudgetCoarsening> coarsened;  ///< largest reduction first
};

/// faces[f]: the prediction of face f (null: not meshed); solidFaces[s]: the faces of solid s
/// (empty for a surface mesh); solidVolumes[s]: its volume (missing or 0: not known, T^{3/2}
/// alone). limit ≤ 0: no budget (fits, predictions filled in).
ElementBudget decideBudget(const std::vector<const FaceSizePrediction*>& faces,
                           const std::vector<std::vector<int>>& solidFaces, double limit, double hMax,
                           const std::vector<double>& solidVolumes = {});

/// The default N for a machine with `availableBytes` of memory: triangles for dim 2, tets
/// (the costlier element) for dim 3.
double defaultElementBudget(double availableBytes, int dim);

}  // namespace aniso
