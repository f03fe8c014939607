#pragma once
// The transition split — the third topological correction of the conversion front (thesis
// 4.7.3, alg. 4.5 step 2, fig. 4.14; Q-Morph's transition split). Where the front edges at a
// vertex v, (v, L) and (v, s), meet at a region angle that is not small (≥ the seam angle)
// but their metric lengths differ by more than splitRatio and the long one is at least
// minLongLength (the size must grow along the front, not the short edge be too short), the
// long edge gets a node so that the size can change gradually:
//   - m at the midpoint of (v, L), c inside the quad Q behind (v, L) (ring v, L, p, q);
//   - Q becomes the two quads (v, q, p, c) and (c, p, L, m) and the triangle (v, c, m),
//     which with the region triangles at v between (v, L) and (v, s) (one or two, split at
//     m) forms the quad (v, c, m, s); the rest of them stays in the region, fanned from m;
//   - v leaves the front for the quad side (it moves between its old place and q).
// The front then runs L → m → s instead of L → v → s: the same number of edges and region
// triangles (parity kept). c and v's new place are chosen among a few candidates (v moved
// towards q by a fraction in moveFractions; c the centroid of (v, m, L, p, q) or of (v, m,
// p) with v at its new place) by the best worst quality of the three new quads.
// Check, then change: v not on the face boundary; (v, L) with a live quad behind it; the
// region at v between the two front edges one or two triangles, none with a corner of Q
// other than v and L; every new element strictly convex and counter-clockwise (QuadShape.h
// convexCCW), the three quads with quality ≥ minQuality, every other element around v
// (which moves) ≥ min(minQuality, its quality before). Otherwise nothing changes.
#include <array>

#include "mesher/quad/TransitionSeam.h"

namespace aniso::quad {

struct TransitionSplitOptions {
  double splitRatio = 2.5;  ///< longer / shorter metric length (Q-Morph: 2.5)
  /// The long edge at least this long in the metric (1 = the target size): where it is the
  /// short edge that is too short, a split would only refine the front.
  double minLongLength = 1.5;
  double minQuality = 0.3;  ///< as the morphed quads (MorphOptions::minQuality)
  std::array<double, 3> moveFractions{0.2, 0.35, 0.5};
};

/// Transition split at the left (`left`: vertex a = corner k) or right end (vertex b) of
/// front edge k of triangle e, between the base edge and the adjacent front edge there, when
/// the angle is not below `seamAngle`, the ratio large and the checks pass. Result fields
/// as TransitionSeam.h: quad = (v, c, m, s), reshaped = (v, q, p, c), extra = (c, p, L, m).
TransitionResult transitionSplit(QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, bool left,
                                 double seamAngle, const TransitionSplitOptions& options = {});

}  // namespace aniso::quad
