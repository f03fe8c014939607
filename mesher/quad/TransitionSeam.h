#pragma once
// The transition seam — the second topological correction of the conversion front (thesis
// 4.7.3, alg. 4.5 step 2, fig. 4.14; Q-Morph's transition seam). Where the two adjacent front
// edges c→a and a→b meet at a small region angle (below the seam's seamAngle, metric) and
// the region there is the single triangle (a, b, c) — the seam's configuration (FrontSeam.h) — but their
// metric lengths differ by more than seamRatio, the seam would join edges of unlike length
// into a poor quad. Instead the longer edge (a, L) is split at its midpoint m:
//   - the quad Q behind (a, L) gives up its corner a for m: Q' = Q with a → m;
//   - the corner it leaves, triangle (a, m, q) (q: a's other neighbour in Q), and the half
//     of (a, b, c) at a, triangle (a, s, m) (s: the shorter edge's far end), form the quad
//     N with the ring a, q, m, s;
//   - the other half, triangle (m, b, c), stays in the region.
// The front then runs L → m → s instead of L → a → s: the same number of edges and region
// triangles (parity kept), and the next correction at m finds edges of similar length.
// Check, then change: (a, L) must have a live quad behind it (not the face boundary); every
// new element strictly convex and counter-clockwise (QuadShape.h convexCCW); N with quality
// ≥ the seam's minQuality, Q' ≥ min(minQuality, Q's quality before). Otherwise nothing
// changes (the vertex added for m is taken back).
#include "mesher/quad/FrontSeam.h"

namespace aniso::quad {

struct TransitionSeamOptions {
  /// Longer / shorter metric length above which the transition seam replaces the seam
  /// (Q-Morph: 2.5). The angle and the quality threshold are the seam's (SeamOptions).
  double seamRatio = 2.5;
};

struct TransitionResult {
  bool done = false;
  int vertex = kNone;    ///< the new front vertex m
  int quad = kNone;      ///< the new quad (N here; TransitionSplit.h: the third quad)
  int reshaped = kNone;  ///< the quad that replaced Q (Q' here)
  int from = kNone;      ///< Q, the quad it replaced (dead now)
  int extra = kNone;     ///< TransitionSplit.h: its second quad made from Q
};

/// Transition seam at the left (`left`: vertex a = corner k) or right end (vertex b) of
/// front edge k of triangle e, when the angle is small, the ratio large and the checks pass.
TransitionResult transitionSeam(QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, bool left,
                                const SeamOptions& seam = {}, const TransitionSeamOptions& options = {});

}  // namespace aniso::quad
