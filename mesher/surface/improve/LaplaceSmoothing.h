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
//     (directions, aspect ratio) enters, not that of its size. Reason, measured: on meshes
//     whose vertex density already follows a graded size (as the refinement of sec. 4.5
//     produces them) the connectivity encodes the gradation — more neighbours on the fine
//     side — and the plain average is close to equilibrium; weighting the neighbours
//     additionally by 1/h at the edge midpoints counts the gradation twice and drags the
//     vertices towards the fine side sweep after sweep (size ×30 across a face: mean η_M
//     0.863 plain, 0.845 verbatim eq. 4.3; the normalised version equals the plain one
//     there), while a rotating anisotropy gains from it (0.841 plain, 0.850 either form).
//     metricSize = true is eq. 4.3 verbatim.
// Check, then change: the move Q → Q' is accepted only when every triangle of the star
// stays counter-clockwise (exact orient2d) and the worst η_M of the star (all star
// triangles measured with the cached metric of Q) stays at least min(its value before the
// move, qualityFloor); otherwise the half move is tried, then the vertex stays. So a star
// whose worst element is below the floor never gets worse, and a good star may trade a
// little of its worst element for its others (qualityFloor = 1: the worst η_M of a star
// never drops; qualityFloor = −∞ with only the orientation check: the thesis' rule, which
// cancels inverting moves only). Measured on random-point meshes (improve_face_test),
// floor 0.5 gives a higher mean η_M than the strict rule with the same minimum.
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
