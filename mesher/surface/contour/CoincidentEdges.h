#pragma once
// CoincidentEdges — model vertices and edges that are one point or one curve in space but
// separate entities in the CAD topology, so that the surface mesh gives them ONE set of
// nodes (thesis 4.3: the contour is discretized once and shared by the faces around it).
//
// Seen in exported assemblies after the boolean that fragments overlapping parts: a solid
// that touches itself along a line keeps two copies of the edge there, each with its own
// end vertices, each used by two faces. Discretized separately, the copies give coincident
// surface nodes, and the volume mesher cannot insert the second one (the solid is lost);
// with only the vertices shared, the parallel-edge rule would split one copy and not the
// other (a node on the other copy's segment, unrecoverable).
//
// Vertices: a and b are one point when |a − b| ≤ max(min(tol_a, tol_b), floor): their CAD
// tolerances (each already claims the other lies within its own ball), or the small-feature
// floor, a distance below which no element could resolve the model (the caller's: the
// fuse's largest fuzzy value, 1e-6 of the diagonal; 0 for none). Two ends of one open edge
// are merged only when the whole edge is shorter than the floor: the edge collapses to a
// point (collapsedEdge). Faces a few micrometres wide along a long edge, meshed, force flat
// tetrahedra (docs/measurements.md). Representatives by
// union-find, the lowest index of each group; a group that would join the two ends of a
// longer open edge through a third vertex cancels every merge (the CAD's vertices kept).
// Edges: a < e are twins when they join the same two represented vertices (an open edge,
// neither degenerate nor collapsed) and three inner points of e (t at 1/4, 1/2, 3/4) and
// the midpoint of a lie within max(tol_a, tol_e, kTwinFloor × the edge's chord, floor) of
// the other curve. `reversed` when e runs from a's end to a's start.
#include <vector>

#include "mesher/model/Model.h"

namespace aniso::contour {

/// rep[v]: the vertex whose node v uses (v itself when it has no coincident partner).
/// Only vertices of `usedEdges` (one flag per model edge) are considered.
std::vector<int> coincidentVertices(const Model& model, const std::vector<char>& usedEdges, double floor = 0);

/// An open edge both of whose ends `rep` merges (shorter than the floor): it is one point.
bool collapsedEdge(const Model& model, int e, const std::vector<int>& rep);

struct EdgeTwins {
  std::vector<int> of;         ///< of[e] = the lower-indexed twin a whose nodes e uses, or −1
  std::vector<char> reversed;  ///< e runs against a
  int count = 0;
};

/// Twin edges among the used ones (see above), with vertices compared through `rep`.
EdgeTwins coincidentEdges(const Model& model, const std::vector<char>& usedEdges, const std::vector<int>& rep,
                          double floor = 0);

}  // namespace aniso::contour
