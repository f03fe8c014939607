#pragma once
// Topological transformations of the quad mesh (thesis 4.8.1, fig. 4.17), by connectivity
// first and guarded by the metric shape:
//   - doublet removal: an inner vertex shared by exactly two quads (a, b, c, v) and
//     (c, d, a, v) is removed and the two become (a, b, c, d);
//   - diagonal collapse of a quad between two valence-3 inner vertices (DiagonalCollapse.h);
//   - diagonal swap: two quads sharing an inner edge form a hexagon H0..H5 split by its
//     diagonal (H0, H3); the edge is turned to (H1, H4) or (H2, H5) when that lowers
//     Σ (valence − ideal)² over the six vertices (ideal 4 inside, round(θ/90°) + 1 on the
//     boundary, θ the metric angle of the boundary vertex) without lowering the worse
//     quad's metric scaled Jacobian below min(its value, minQuality), or keeps the valence
//     sum and raises the worse quad's scaled Jacobian by more than qualityGain.
// Check, then change: the new quads must be strictly convex and counter-clockwise.
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

struct TopologyOptions {
  double minQuality = 0.3;
  double qualityGain = 0.1;
  int sweeps = 2;
};

struct TopologyStats {
  int doublets = 0, swaps = 0, collapses = 0;
};

TopologyStats improveTopology(QuadMesh2d& mesh, VertexMetrics& metrics, const TopologyOptions& options = {});

}  // namespace aniso::quad
