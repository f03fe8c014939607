#pragma once
// Improvement of a face triangulation (thesis sec. 4.6, alg. 4.2), in the face's metric.
// Each pass (N_imp passes, default 2) first evaluates the control space once at every
// vertex (VertexMetricCache.h; the metric stays cached for the whole pass), then:
//   - mixed metric Laplace smoothing (4.6.1, eq. 4.2–4.3, LaplaceSmoothing.h): each free
//     vertex moved towards the average of its neighbours — the plain average where the
//     local metric gradation is low (the metric is then locally constant and the plain
//     average *is* the metric-space average), the metric version 4.3 where it is high (by
//     default with the mid-edge metrics scaled to the vertex's size, LaplaceSmoothing.h
//     explains why) — never inverting an adjacent triangle, and only when the star gets
//     better in η_M (its worst element below smoothingQualityFloor, else its mean; the
//     move is halved, then cancelled: check, then change);
//   - topological swap (4.6.2, TopologicalSwap.h) in areas of low metric gradation: flip an
//     edge when it brings the vertex degrees closer to their ideal (6 inside), provided the
//     new diagonal is acceptable to the geometric swap that follows (else the geometric
//     swap would undo it at once);
//   - geometric swap (4.6.3, GeometricSwap.h): flip an edge when the inner-angles criterion
//     in metric space (the metric of each quadrilateral) prefers the other diagonal by more
//     than swapAngleTolerance, repeated until no edge violates it;
// and after the passes:
//   - postprocessing (4.6.4, Postprocess.h) of the triangles with η_M below a threshold:
//     quality-improving flips of their edges, flips combined with moving a vertex out of the
//     way, and local optimisation of their free vertices.
// Constrained edges (the face boundary) are never flipped; vertices flagged fixed (the
// boundary vertices) never move, nor do vertices on a constrained edge or on the border of
// the triangulation, nor vertices where the control space returns an unusable metric. The
// result is a valid triangulation (every triangle counter-clockwise in (u, v), exact
// orient2d) with the same vertices, boundary and constrained edges. Deterministic (vertices
// and edges visited by index). Not thread-safe for one triangulation; different
// triangulations may be improved concurrently (cs is only read).
#include <cstdint>
#include <vector>

#include "mesher/core/Cancel.h"
#include "mesher/control/ControlSpace2d.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/surface/face/SurfaceLift.h"

namespace aniso {

struct ImproveOptions {
  int passes = 2;               ///< N_imp
  int smoothingIterations = 2;  ///< Laplace sweeps per pass
  bool topologicalSwap = true;
  bool geometricSwap = true;
  bool postprocess = true;
  /// "Low metric gradation" (sec. 4.6.1, 4.6.2): the largest metric difference δ_M
  /// (eq. 2.24–2.25) between a vertex's metric and its neighbours' below which the metric
  /// counts as locally constant. 0.05 ≈ neighbouring sizes within a factor 1.2.
  double lowGradation = 0.05;
  /// Smoothing acceptance (LaplaceSmoothing.h): stars whose worst η_M is below this floor
  /// must raise it; the others must keep it above the floor and not lower their mean.
  double smoothingQualityFloor = 0.5;
  /// Eq. 4.3 verbatim (true) or with the size of the mid-edge metrics normalised to the
  /// vertex's (false, LaplaceSmoothing.h).
  bool smoothingMetricSize = false;
  /// Tolerance (radians) of the inner-angles criterion in the passes: the geometric swap
  /// flips when the two angles opposite an edge exceed π + tolerance, and the topological
  /// swap only makes diagonals that satisfy that. 0 = the plain Delaunay criterion (then
  /// the topological swap only acts on exactly cocircular quadrilaterals). 0.3 (≈ 17°) gave
  /// the best mean η_M on random-point meshes (docs/measurements.md).
  double swapAngleTolerance = 0.3;
  /// Postprocessing threshold: triangles with η_M below it are improved locally. 0.6 lifts
  /// the worst triangles more than 0.4, at no measurable cost (docs/measurements.md).
  double badQuality = 0.6;
  /// The fold guard (face/SurfaceLift.h), may be null: no operator turns a triangle over
  /// on the surface.
  const face::SurfaceLift* lift = nullptr;
  /// Checked before every pass (Cancel.h); null: never stops.
  const CancelToken* cancel = nullptr;
};

struct ImproveStats {
  long long moves = 0, topologicalSwaps = 0, geometricSwaps = 0;
  long long rejectedMoves = 0;         ///< smoothing moves cancelled by the checks
  long long postprocessFlips = 0, postprocessMoves = 0;
  long long badBefore = 0, badAfter = 0;  ///< triangles below badQuality around postprocessing
};

/// `fixed[v]` true for vertices that must not move (boundary); vertices not referenced by
/// any live triangle are ignored. Throws MeshingError when fixed.size() < tri.numVertices()
/// or an option is out of range (passes or iterations < 0, a threshold not finite).
ImproveStats improveFaceMesh(del2d::Triangulation2d& tri, const ControlSpace2d& cs,
                             const std::vector<std::uint8_t>& fixed, const ImproveOptions& options = {});

}  // namespace aniso
