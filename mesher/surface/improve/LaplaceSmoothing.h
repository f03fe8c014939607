#pragma once
// Mixed metric Laplace smoothing (thesis sec. 4.6.1, eq. 4.2–4.3).
//
// Each sweep visits the movable vertices (VertexMetricCache) in index order, Gauss–Seidel
// (a vertex sees its neighbours' new positions). The target of vertex Q with neighbours
// P_1..P_n (its closed star, n = NE(Q)):
//   - low local gradation (g_Q ≤ lowGradation): Q' = (1/n) Σ P_i (eq. 4.2). For a metric
//     constant around Q this is exactly the metric-space average M⁻¹ (1/n) Σ M P_i, since
//     M is linear;
//   - otherwise the metric version (eq. 4.3): x^M = (1/n) Σ M_i (P_i − Q) with M_i the
//     metric at the middle of QP_i (eq. 2.18 between the cached metrics of Q and P_i), and
//     Q' = Q + M_Q⁻¹ x^M. The thesis writes the plain sum Σ; the mean is taken here so that
//     a constant metric gives back eq. 4.2 (the sum would overshoot n-fold).
//     Size normalisation (metricSize = false, the default; documented deviation): each M_i
//     is scaled to the determinant of M_Q, so only the variation of the metric's shape
//     (directions, aspect ratio) enters, not that of its size. Reason: on meshes
//     whose vertex density already follows a graded size (as the refinement of sec. 4.5
//     produces them) the connectivity encodes the gradation — more neighbours on the fine
//     side — and the plain average is close to equilibrium; weighting the neighbours
//     additionally by 1/h at the edge midpoints counts the gradation twice and drags the
//     vertices towards the fine side sweep after sweep (docs/measurements.md).
//     metricSize = true is eq. 4.3 verbatim.
// Check, then change: the move Q → Q' is accepted only when every triangle of the star
// stays counter-clockwise (exact orient2d) and the star gets better, each star triangle
// measured by η_M in the blend of its three vertices' cached metrics
// (VertexMetricCache::blend):
//   - a poor star (worst η_M below qualityFloor): its worst η_M increases;
//   - otherwise: its worst η_M stays ≥ qualityFloor and its mean η_M does not decrease;
// else the half move is tried, then the vertex stays. The thesis only cancels inverting
// moves. The quality conditions ("smart" Laplacian) keep the smoothing from degrading a
// good mesh: on face-mesher output (AN1, k = 2) mean η_M after 2 / 3 / 4 passes was
// 0.952 / 0.948 / 0.943 with the orientation and floor checks alone (each pass made it
// worse), 0.957 / 0.958 / 0.959 with these. qualityFloor = 1: every move must raise the
// worst η_M of its star (max-min smoothing); −∞: mean-only.
// Scratch buffers are allocated once per call, not per vertex.
#include "mesher/surface/improve/VertexMetricCache.h"

namespace aniso::improve {

struct SmoothingOptions {
  int iterations = 2;          ///< sweeps over all movable vertices
  double lowGradation = 0.05;  ///< δ_M threshold of the mixed approach; < 0: always eq. 4.3
  double qualityFloor = 0.5;   ///< see above; ≤ 1
  bool metricSize = false;     ///< eq. 4.3 with the size variation of the metric too (see above)
};

struct SmoothingStats {
  long long visited = 0;    ///< movable vertices visited (summed over sweeps)
  long long moved = 0;      ///< moves accepted (full or halved)
  long long halved = 0;     ///< of which the halved move
  long long rejected = 0;   ///< both moves refused by the checks
  long long metricVersion = 0;  ///< targets computed with eq. 4.3
};

/// The metrics must have been updated for tri (same vertex count). Fixed and immovable
/// vertices are never written. Throws MeshingError when metrics.size() != tri.numVertices()
/// or an option is invalid.
SmoothingStats laplaceSmoothing(Triangulation2d& tri, const VertexMetricCache& metrics,
                                const SmoothingOptions& options = {});

}  // namespace aniso::improve
