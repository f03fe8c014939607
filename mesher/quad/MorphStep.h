#pragma once
// One step of the conversion by morphing (thesis 4.7.3, alg. 4.5, after Owen's Q-Morph),
// for the base front edge k of triangle e (a→b, triangle on the left):
//   1 the topological corrections of fig. 4.14 at either end, by the angle and the metric
//     length ratio of the base and the adjacent front edge: at a small angle the transition
//     seam (TransitionSeam.h) when the ratio is large, else the seam (FrontSeam.h); at a
//     wider angle the transition split (TransitionSplit.h) when the ratio is large. One that
//     applies changes the front and ends the step (the caller reclassifies);
//   2 side edges at a and at b by angle in metric space (SideEdge.h), giving c and d;
//   3 the upper edge (c, d) recovered by swaps (TopEdgeRecovery.h);
//   4 the triangles enclosed by a→b→d→c→a (an even number, 2 + 2 × the vertices inside)
//     are replaced by the quad (a, b, d, c), their inner vertices dropped;
//   5 local smoothing ahead of the front: the region vertices next to the new quad move
//     to the metric mean of their neighbours when every triangle around stays strictly
//     convex and the worst of them does not get worse.
// Check, then change: the quad strictly convex with scaled Jacobian ≥ minQuality (QuadShape.h
// elementQuality), at most maxEnclosed triangles, the enclosed set bounded by exactly the
// four edges, and the removal must keep every region component even (RegionParity.h) when
// c or d is on the front. A failed step leaves the mesh valid (side and upper edge swaps
// may stay) and returns no quad: the caller falls back to merging (alg. 4.5's fallback).
#include <cstdint>

#include "mesher/quad/FrontSeam.h"
#include "mesher/quad/RegionParity.h"
#include "mesher/quad/SideEdge.h"
#include "mesher/quad/TransitionSplit.h"

namespace aniso::quad {

struct MorphOptions {
  double minQuality = 0.3;  ///< morphing sets high standards; merging takes what it leaves
  int maxEnclosed = 12;
  int smoothSweeps = 2;
  SideOptions side;
  SeamOptions seam;
  TransitionSeamOptions transitionSeam;
  TransitionSplitOptions transitionSplit;
};

/// Why a morphing step formed nothing (for the statistics).
enum class MorphFailure { None, Side, Degenerate, Shape, TopEdge, Enclosed, Parity };

struct MorphResult {
  MorphFailure failure = MorphFailure::None;
  int quad = kNone;     ///< the new quad, or kNone
  int seamVertex = kNone;  ///< a seam was closed at this vertex (quad == kNone)
  int seamElement = kNone;
  TransitionResult transition;  ///< a transition seam or split was made (quad == kNone)
  bool split = false;           ///< it was the transition split
};

/// `onFront[v]`: v is a boundary vertex or a corner of a quad (the caller's bookkeeping); a
/// vertex beyond its size (made by this step's splits) is not on the front.
MorphResult morphFrontEdge(QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k,
                           const std::vector<std::uint8_t>& onFront, RegionParity& parity,
                           const MorphOptions& options = {});

}  // namespace aniso::quad
