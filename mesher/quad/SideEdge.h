#pragma once
// Side edges of a morphed quad (thesis 4.7.3, alg. 4.5 steps 2 and 5, fig. 4.13(a)–(b),
// after Owen's Q-Morph). The base front edge a→b has its triangle on the left; the side
// edge at a (left) and at b (right) is chosen by the region's inner angle α there, in the
// metric of the vertex:
//   - α < sideAngle (3π/4): the adjacent front edge itself;
//   - else the region edges from the vertex within bisectorTolerance (π/6) of the
//     bisector of α, closest first (the caller takes the pair of sides giving the best quad);
//   - else the edge opposite the vertex in the triangle the bisector runs through is
//     swapped (when both triangles are in the region and their union strictly convex), and
//     the new edge taken when within the tolerance;
//   - the best inner candidate longer (metric) than maxLengthRatio × the base edge is split
//     at its midpoint (its two triangles become four), the midpoint taken instead (fig.
//     4.13(b): side edges made by swapping or splitting).
// The fan (regionFan) lists the region's triangles around the vertex from the base
// triangle, counter-clockwise at a and clockwise at b, with the rays between them and
// their cumulative metric angles.
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

struct SideOptions {
  double sideAngle = 2.35619449019234492885;          ///< 3π/4
  double bisectorTolerance = 0.52359877559829887308;  ///< π/6
  double maxLengthRatio = 1.5;
};

struct RegionFan {
  std::vector<int> triangles;  ///< f_0 (the base triangle), f_1, …
  std::vector<int> rays;       ///< ray j is the far vertex of the edge before f_j; rays[0] the base edge's other end
  std::vector<double> angle;   ///< metric angle of ray j from ray 0 (angle[0] = 0)
  bool closed = false;         ///< the walk came back to f_0 (no front at the vertex)
};

/// The fan at v of the region, from triangle e (which has v) turning counter-clockwise
/// (`ccw`, left end) or clockwise (right end).
RegionFan regionFan(const QuadMesh2d& mesh, VertexMetrics& metrics, int v, int e, bool ccw);

struct SideEdge {
  std::vector<int> vertices;  ///< far ends of the candidate side edges, best first; empty when none
  bool front = false;  ///< the adjacent front edge was used
  bool swapped = false;
  bool split = false;
};

/// The side edge at the left (`left`, vertex a) or right end (vertex b) of front edge k of
/// triangle e. May swap one edge of the region (then e's id may change: the caller finds
/// its base triangle again by its edge).
SideEdge selectSideEdge(QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, bool left,
                        const SideOptions& options = {});

/// The live triangle with the directed edge a→b, searched around a from element `hint`
/// (any live element with corner a), or kNone.
int triangleWithEdge(const QuadMesh2d& mesh, int a, int b, int hint);

}  // namespace aniso::quad
