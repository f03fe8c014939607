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
// Check, then change: the move Q → Q' is accepted only when every triangle of the star
// stays counter-clockwise (exact orient2d) and the smallest η_M of the star (all star
// triangles measured with the cached metric of Q) does not decrease; otherwise the half
// move is tried, then the vertex stays. The thesis only cancels inverting moves; the
// quality guard additionally keeps smoothing from creating worse elements near concave
// borders and in strongly graded areas.
// Scratch buffers are allocated once per call, not per vertex.
#include "mesher/surface/improve/VertexMetricCache.h"

namespace aniso::improve {

struct SmoothingOptions {
  int iterations = 2;          ///< sweeps over all movable vertices
  double lowGradation = 0.05;  ///< δ_M threshold of the mixed approach; < 0: always eq. 4.3
};

struct SmoothingStats {
  long long visited = 0;    ///< movable vertices visited (summed over sweeps)
  long long moved = 0;      ///< moves accepted (full or halved)
  long long halved = 0;     ///< of which the halved move
  long long rejected = 0;   ///< both moves refused by the checks
  long long metricVersion = 0;  ///< targets computed with eq. 4.3
};

/// The metrics must have been updated for tri (same vertex count). Fixed and immovable
/// vertices are never written. Throws MeshingError when metrics.size() != tri.numVertices().
SmoothingStats laplaceSmoothing(Triangulation2d& tri, const VertexMetricCache& metrics,
                                const SmoothingOptions& options = {});

}  // namespace aniso::improve
