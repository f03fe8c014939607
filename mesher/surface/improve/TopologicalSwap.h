#pragma once
// Topological edge swap (thesis sec. 4.6.2): evens out the vertex degrees. The edge P1P3
// of the quadrilateral P1P2P3P4 is swapped to P2P4 when
//   1. the quadrilateral is strictly convex (del2d::canFlip, which also refuses
//      constrained edges), and
//   2. NE(P1) + NE(P3) > NE(P2) + NE(P4) + 2,
// only where the metric gradation is low (all four vertices' g ≤ lowGradation,
// VertexMetricCache), so as not to destroy the gradation of the mesh, and never at a
// frozen triangle (touching a pole, VertexMetricCache). Each edge is checked
// once per call (triangle slots in index order, each interior edge from its lower-index
// triangle).
//
// Generalisation (documented choice): NE is taken relative to the vertex's ideal degree
// (6 inside, fewer on the border, VertexMetricCache::idealDegree), i.e. with the excess
// e = NE − ideal the condition is e1 + e3 > e2 + e4 + 2. Inside this is the thesis' rule;
// on the border it stops the swap from piling edges onto border vertices. Either way each
// swap lowers Σ e² by at least 2.
//
// Optional geometric guard: with a finite angleTolerance the new diagonal must satisfy the
// inner-angles criterion within that tolerance (GeometricSwap.h), so that the geometric
// swap run afterwards in alg. 4.2 does not flip it straight back.
#include <limits>

#include "mesher/surface/improve/VertexMetricCache.h"

namespace aniso::improve {

struct TopologicalSwapOptions {
  double lowGradation = 0.05;
  /// Radians; infinity = no geometric guard (the thesis' rule alone).
  double angleTolerance = std::numeric_limits<double>::infinity();
};

struct TopologicalSwapStats {
  long long checked = 0;  ///< interior unconstrained edges considered
  long long flipped = 0;
};

/// Throws MeshingError when metrics.size() != tri.numVertices().
TopologicalSwapStats topologicalSwap(Triangulation2d& tri, const VertexMetricCache& metrics,
                                     const TopologicalSwapOptions& options = {});

}  // namespace aniso::improve
