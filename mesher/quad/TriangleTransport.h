#pragma once
// Pairing of the triangles left by the conversion (thesis 4.7: an all-quad mesh wherever
// the boundary counts are even). A face whose boundary loops are all even has an even
// number of triangles in every edge-connected part (3T + 4Q = 2E_i + E_b), so the
// triangles left over can be paired up: for each one, the nearest other triangles (by a
// breadth-first search through the elements) are tried in turn as its partner; the chain
// of elements between the two is re-quadrangulated as a whole (ChainQuadrangulation.h), or
// else the triangle walks towards the partner's centroid — at each step, over the quads next to it,
// the pentagon (triangle ∪ quad) is cut into a quad and a triangle (five ways), the legal
// cut bringing the triangle's centroid nearest to the goal taken, and only if it comes
// nearer (so the walk ends) — until the two share an edge, and then they are merged, or,
// when that quad would be poor, split into five quads (PairSplit.h). After the rounds, two
// adjacent triangles still left are split with a quad next to them into four quads
// (HexagonSplit.h: a flat boundary vertex or a sharp corner in the pair).
// Check, then change: every cut and the final merge must give strictly convex,
// counter-clockwise elements with quads of scaled Jacobian ≥ minQuality (QuadShape.h);
// when the walk cannot be completed its moves are undone and the next partner is tried.
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

struct TransportOptions {
  double minQuality = 0.1;
  int maxPathLength = 64;  ///< partner search depth (elements) and walk length (steps)
  int partners = 10;       ///< nearest triangles tried, in turn, for each triangle
  int rounds = 6;
};

struct TransportStats {
  int paired = 0;   ///< pairs merged into quads
  int splitPairs = 0;  ///< of which split into five quads (PairSplit.h)
  int hexagonSplits = 0;  ///< of which split into four quads with a quad next to them (HexagonSplit.h)
  int chains = 0;      ///< of which by re-quadrangulating the chain between them (ChainQuadrangulation.h)
  int moves = 0;    ///< pentagon cuts
  int triangles = 0;  ///< live triangles left
  int failedCuts = 0;   ///< walks stuck (no legal cut brings the triangle nearer)
  int failedPairs = 0;  ///< walks that reached the partner but could not merge with it
};

TransportStats pairTriangles(QuadMesh2d& mesh, VertexMetrics& metrics, const TransportOptions& options = {});

}  // namespace aniso::quad
