#pragma once
// MeshOptions — every parameter of the meshing process in one struct, passed down by
// reference; no globals (STYLE.md). The struct's defaults are the thesis' table 3.2 (the
// unit tests follow them); the program's are SizingParameters::forAnalysis().
#include <memory>
#include <numbers>
#include <optional>
#include <string>

#include "mesher/core/Cancel.h"

namespace aniso {

/// Elements per full circle (2π) of the program's default curvature sizing: Gmsh's
/// `-clcurv 12` convention, a mesh for a first FEM analysis (docs/defaults_vs_gmsh.md: with
/// the thesis' γ_c 0.15, i.e. 42 per circle, tet counts were 10–40× Gmsh's).
inline constexpr double kDefaultElementsPerCircle = 12;

/// The program's default h_max over the model diagonal: Gmsh's default size (a unit cube's
/// edges get 6 segments: diagonal / 10). Against the thesis' 0.5 it refines small blocks and
/// costs real parts no more tets (a surface graded from smaller sizes needs fewer tets to reach
/// the quality bar; docs/measurements.md).
inline constexpr double kDefaultHmaxRel = 0.1;

/// The program's default chord deviation over the model diagonal (chordDeviationRel):
/// 12 per circle alone lose volume and area on large radii (docs/defaults_vs_gmsh.md;
/// docs/census.md, session 13).
inline constexpr double kDefaultChordDeviationRel = 5e-4;

/// γ_c (edge length / curvature radius) for n elements per full circle: 2π/n. n > 0.
inline double curvatureRatioForElementsPerCircle(double n) { return 2 * std::numbers::pi / n; }
/// Elements per full circle for γ_c: 2π/γ_c.
inline double elementsPerCircleForCurvatureRatio(double ratio) { return 2 * std::numbers::pi / ratio; }

/// The element size (README, "Element size"). Every length is in model units (millimetres
/// for STEP and IGES, whose readers convert; the file's own unit for BREP). Sources of size:
/// the target h_max (--size, --hmax or --hmax-rel), the curvature (γ_c, unless `curvature`
/// is off), the contour curvature, the thin parts (proximity) and the user's sources; each
/// is bounded to [h_min, h_max], so h_min and h_max are hard bounds of the requested size.
struct SizingParameters {
  double anisotropy = 5.0;          ///< γ_a, max h_max/h_min of a metric (eq. 2.42)
  double gradation = 4.0;           ///< γ_M, metric gradation ratio (eq. 2.26–2.32)
  double curvatureRatio = 0.15;     ///< γ_c, edge length / curvature radius (eq. 2.41)
  double contourAnisotropy = 2.0;   ///< γ_ac, anisotropy for contour curvature (eq. 2.46);
                                    ///< the thesis requires γ_ac ≤ γ_a: use contourAnisotropyEff()
  double hmaxRel = 0.5;             ///< γ_hmax, h_max = γ_hmax · model diagonal
  double hminRel = 1e-4;            ///< γ_hmin, h_min = γ_hmin · model diagonal
  double metricDistanceEps = 1e-5;  ///< ε_M, threshold for distance in metric space
  double metricDifferenceEps = 0.2; ///< ε_δ, threshold for metric difference (3.3.1)
  double adaptLengthMax = 2.0;      ///< l_Mmax, metric length threshold for adaptation
  /// δ / model diagonal: the largest distance of an edge's chord from a curved face or
  /// edge (h ≤ sqrt(8 δ / κ) beside eq. 2.41's γ_c / κ: BRepMesh's linear deflection beside
  /// the angular one); 0: none (the thesis' sizing), the program's default is
  /// kDefaultChordDeviationRel. 12 per circle alone lose 4.5 % of a cylinder's volume and
  /// ~6 % of a sphere's.
  double chordDeviationRel = 0;
  std::optional<double> hmax;       ///< absolute h_max (overrides hmaxRel)
  std::optional<double> hmin;       ///< absolute h_min (overrides hminRel)
  /// --size: the target size everywhere (h_max = size); curvature, thin parts and sources
  /// still refine below it, down to h_min, unless `curvature` is off.
  std::optional<double> size;
  bool curvature = true;            ///< curvature sources (surface and contour); off: uniform h_max

  /// The program's defaults: the thesis' table with the curvature of
  /// kDefaultElementsPerCircle (γ_c = 2π/12 ≈ 0.52) and h_max a tenth of the diagonal
  /// (kDefaultHmaxRel).
  static SizingParameters forAnalysis() {
    SizingParameters p;
    p.curvatureRatio = curvatureRatioForElementsPerCircle(kDefaultElementsPerCircle);
    p.hmaxRel = kDefaultHmaxRel;
    p.chordDeviationRel = kDefaultChordDeviationRel;
    return p;
  }

  double contourAnisotropyEff() const { return contourAnisotropy < anisotropy ? contourAnisotropy : anisotropy; }
  /// h_max for a model of the given diagonal.
  double hmaxFor(double diagonal) const {
    if (size) return *size;
    return hmax ? *hmax : hmaxRel * diagonal;
  }
  /// h_min for a model of the given diagonal (never above h_max; check() refuses an
  /// explicit h_min above an explicit h_max or size).
  double hminFor(double diagonal) const {
    const double h = hmin ? *hmin : hminRel * diagonal;
    return h < hmaxFor(diagonal) ? h : hmaxFor(diagonal);
  }
  /// Empty when the parameters make sense, else a message naming the first bad one.
  std::string check() const;
};

/// How --quad converts triangles (thesis 4.7): merging (alg. 4.4), morphing (alg. 4.5) or
/// the mixed method (alg. 4.3).
enum class QuadMethod { Merge, Morph, Mixed };

/// What becomes of faces inside a solid (ModelSolid::embedded) in a volume mesh: Auto, a
/// crack where the CAD says so (a shell of only internal faces: zero thickness) and bonded
/// otherwise; Crack, every one two-sided; Bond, every one one-sided, its nodes shared by
/// the tetrahedra on both sides (--internal-faces).
enum class InternalFaces { Auto, Crack, Bond };

struct MeshOptions {
  int dim = 0;          ///< 2 or 3; 0 = 3 when the model has solids, else 2
  int order = 1;        ///< 1 linear, 2 quadratic
  bool quad = false;    ///< quad-dominant surface meshes
  QuadMethod quadMethod = QuadMethod::Merge;  ///< --quad-method
  int threads = 0;      ///< 0 = all cores
  InternalFaces internalFaces = InternalFaces::Auto;
  SizingParameters sizing;
  std::string sizingFile;  ///< user sizing sources (--sizing FILE.json)
  /// Element budget checked before meshing (mesher/sizing/ElementBudget.h): triangles, plus
  /// tets for a volume mesh. ≤ 0: none.
  double maxElements = 0;
  /// Stops the run (--time-limit; Cancel.h); shared by every copy of the options, null:
  /// never stops.
  std::shared_ptr<const CancelToken> cancel;
};

}  // namespace aniso
