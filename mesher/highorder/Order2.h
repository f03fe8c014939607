#pragma once
// Quadratic elements (--order 2): one mid-edge node per mesh edge, shared by every element
// using the edge, placed on the geometry the edge lies on, then checked for validity.
//
// Placement (surface/MidEdgeGeometry.h):
//   - an edge along a model edge (its two nodes consecutive on that edge's discretization):
//     on the 3D curve, at the projection of the chord midpoint started from the parameter
//     midpoint of the two nodes' t (near the arc-length midpoint; a closed edge's vertex
//     takes t0 or t1, whichever its neighbour is next to), NodeOn{Edge, e, t};
//   - an edge inside a face: on the surface, at the projection of the chord midpoint started
//     from the (u, v) midpoint of its nodes (seams and periodic parameters: the two nodes'
//     representatives nearest each other; a pole: the pole's (u, v) nearest the other
//     node), or at the (u, v) midpoint's image if that is nearer the chord midpoint; when
//     both are far from it (a seam the surface does not declare periodic), the projections
//     started from either end are tried too. NodeOn{Face, f, uv};
//   - an edge inside a solid (tetrahedra only): the straight midpoint, NodeOn{Solid, s}.
// Nodes are appended to the mesh's nodes after the existing ones, in the order of first use
// (elements in order, edges in element order): deterministic.
//
// Validity (QuadraticJacobian.h): the Jacobian determinant of every element at its corners
// and its centroid must be at least kMinJacobianRatio times the straight element's — for
// triangles and quads on surfaces the 3D Jacobian measured along the straight element's
// normal. An element failing it gets its curved mid nodes put back at their chord
// midpoints, the most displaced first, until it passes; since mid nodes are shared this is
// repeated until no element fails (it ends: nodes only ever go from curved to straight,
// and a straight valid linear element passes). Such elements are counted as straightened.
// A straightened mid node keeps the NodeOn of the entity its edge lies on (so it stays in
// that face's or edge's groups), though it lies on the chord.
#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/VolumeMesh.h"

namespace aniso {

/// Below this fraction of the straight element's Jacobian determinant, a curved element
/// counts as inverted (a margin so that round-off does not decide validity).
inline constexpr double kMinJacobianRatio = 1e-3;

struct Order2Stats {
  long long midNodes = 0;      ///< mid-edge nodes created
  long long straightened = 0;  ///< elements left straight because curving would invert them
};

/// Fills triangleMid (and quadMid when the mesh has quads) and appends the mid nodes.
/// Throws MeshingError when the mesh is already quadratic or inconsistent with the model
/// (a node entity out of range).
Order2Stats elevateToOrder2(const Model& model, SurfaceMesh& mesh);

/// The same for a volume mesh: the surface's mid nodes first (surface.triangleMid), then
/// tetMid, sharing the surface's node on every boundary edge. Validity is enforced on the
/// tetrahedra and the boundary triangles together.
Order2Stats elevateToOrder2(const Model& model, VolumeMesh& mesh);

}  // namespace aniso
