#pragma once
// Boundary postprocessing of the quad mesh (thesis 4.8.3, the last step of alg. 4.6:
// "special care is taken of the quality of elements adjacent to the boundaries of the
// domain, as they are usually important for the further simulation process").
//
// The boundary layer is the set of live elements with a corner on the face boundary. The
// Laplace smoothing (QuadSmoothing.h) moves a vertex toward the metric centroid of its
// neighbours, which is right for sizes but blind to the angles a fixed, possibly curved or
// kinked boundary imposes on the first layer. Here every free vertex of the boundary layer
// whose star holds an element below `careBelow` is moved by a local optimisation: a compass
// (pattern) search in the vertex's metric space (8 directions, steps from `initialStep`
// halving down to `finalStep`, in metric lengths) over the quality of the vertex's star
// (elementQuality: the 3D scaled Jacobian of quads, the metric shape of triangles). A trial
// position is taken only when the star stays strictly convex and counter-clockwise (exact),
// neither its worst element nor its worst quad gets worse, and worst + meanWeight × mean
// rises by more than `minGain` (pure max–min, meanWeight 0, raises the worst boundary quads
// but lowers the layer's mean; 0.5 raises both: docs/measurements.md); the
// vertex never goes further than `maxDisplacement` (metric length) from where the
// smoothing left it, and the metric length of every edge at the vertex stays at least
// `shortestEdge` × the shortest edge of its star on entry (or its own length, if shorter)
// and at most max(longestEdge, its length): the scaled Jacobian is blind to size, and
// unconstrained a vertex slides next to a boundary vertex and leaves well-shaped but tiny
// quads. The first layer may still shrink toward a boundary finer than the metric (short
// CAD edges, curvature-refined contours), which is where most poor boundary quads are.
// Boundary vertices, and vertices of elements touching a pole (frozenVertices), never
// move: the boundary and the conformity with neighbouring faces are unchanged.
// Deterministic: vertices visited in index order, `sweeps` Gauss–Seidel sweeps.
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

struct BoundaryPostprocessOptions {
  int sweeps = 3;
  double careBelow = 0.8;         ///< a star whose worst element is at least this is left alone
  double initialStep = 0.2;       ///< first trial step, metric length
  double finalStep = 0.0125;      ///< the search stops below this step
  double maxDisplacement = 0.5;   ///< metric length from the vertex's position on entry
  double minGain = 1e-3;          ///< least rise of the score (worst + meanWeight × mean) that counts
  double meanWeight = 0.5;        ///< weight of the star's mean quality in the score
  double shortestEdge = 0.5;      ///< relative to the star's shortest edge on entry
  double longestEdge = 2.0;       ///< metric length an edge at the vertex may grow to
};

struct BoundaryPostprocessStats {
  int candidates = 0;             ///< free boundary-layer vertices with a poor star
  int moved = 0;                  ///< vertex moves taken (over all sweeps)
  double worstBefore = 2, worstAfter = 2;  ///< worst boundary-layer element quality
};

BoundaryPostprocessStats postprocessBoundaryLayer(QuadMesh2d& mesh, VertexMetrics& metrics,
                                                  const BoundaryPostprocessOptions& options = {});

/// The worst quality (elementQuality) over the live elements with a corner on the face
/// boundary; 2 when there is none.
double worstBoundaryLayerQuality(const QuadMesh2d& mesh, VertexMetrics& metrics);

}  // namespace aniso::quad
