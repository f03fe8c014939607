#pragma once
// mendSurfaceSlivers — removes the surface triangles that force flat tetrahedra, before
// the volume is meshed (issue 5: smallest dihedral angle >= 2 degrees "where the boundary
// allows it").
//
// Every tet on a cap (a boundary triangle with an angle near 180 degrees) has a dihedral
// angle near 180 degrees, and every tet holding a boundary edge much shorter than its
// other edges has a dihedral angle near 0 (the short edge subtends a small angle from the
// opposite edge): no volume operator removes them. Both come from the CAD, where the
// surface mesher must follow it: at the tip of a fillet two CAD edges run together
// (docs/measurements.md), and the strip of the face between them is meshed with caps (a
// node of one edge between two nodes of the other) and with node pairs a few micrometres
// apart.
//
// Two operations, each checked before the change, within the local tolerance: the larger
// of `tolerance` (a geometric tolerance) and kLocalSliverRatio times the local size (for a
// merge the smaller longest edge of the two triangles on the edge, for a cap flip the
// cap's edge (a, b)) — the surface moves by at most
// that much. The local part removes what the CAD forces below the local size, which no
// tet on it survives: a face a few micrometres wide between two edges (a step left by
// merged overlapping parts) meshed with 0.1 mm triangles is all caps.
//  1 merge: an edge (a, c) shorter than the local tolerance is collapsed — c's triangles take a,
//    the two triangles on (a, c) vanish. The node kept is the more constrained one (CAD
//    vertex, then edge, then face node); of two alike, the lower index, else the other
//    when that one's collapse is illegal. A CAD vertex node is removed only into another
//    (a CAD edge shorter than the tolerance vanishes: its tets could not keep a dihedral
//    angle above its length over the local size). Legal when every edge at c is used by
//    exactly two triangles (no assembly interface or open rim there), the link condition
//    holds (a and c share exactly the two opposite nodes of (a, c)), and every moved
//    triangle keeps a non-zero area and the side its normal points to. The local part does
//    not apply across a film's rim (an edge whose triangles all lie on faces
//    mesher/model/EdgeNormals.h's filmRims names): the rim is as narrow as the film is
//    thick everywhere, so merging it would slope the film's top down to its bottom around
//    its edge, losing volume and flattening the tets there, not removing a sliver.
//  2 cap flip: a triangle (a, b, c) with an angle above kCapAngleDeg at c, whose edge
//    (a, b) is used by exactly one other triangle (a, b, d), is replaced with (a, b, d) by
//    (a, c, d) and (c, b, d), both on d's face — the edge flip of the quad; across a CAD
//    edge this moves the cap's node c onto the edge's discretisation. Legal when c lies
//    within the local tolerance of the plane of (a, b, d) (the surface does not move by more) or,
//    with a model and both triangles on one face, when the new edge (c, d) lies nearer the
//    CAD surface than (a, b) (their midpoints against MidEdgeGeometry's mid nodes: a cap
//    spanning a pole chord across the face — wing_fuselage's nose, a face triangle lying in
//    the symmetry plane on the other face's triangles — is flipped onto the surface),
//    the edge (c, d) is not in the mesh (a cap on a film's rim flipped onto another face:
//    within the geometric tolerance only), both new triangles turn the normal of (a, b, d)
//    by less than kCapFlipTurnDeg, and neither meets its outer neighbour much sharper
//    than (a, b, d) did (a fold; a cap neighbour's normal does not count).
// The removed area is that of caps and of triangles on sub-tolerance edges: the closed,
// oriented surface stays closed and oriented and conforming; nodes left in no triangle
// stay in the node array. Passes over the triangles in index order until nothing changes
// (at most kMaxSliverPasses); after the first, a pass visits only the triangles within one
// edge of a node the pass before changed (the others would be refused again: the same
// result as a full pass); deterministic. The mesh must be linear triangles (no quads,
// no mid nodes).
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

/// Angle (degrees) above which a triangle is a cap.
inline constexpr double kCapAngleDeg = 150.0;
/// The local part of the tolerance: this fraction of the local size (see above). An edge
/// this much shorter than its triangle, or a cap this flat, is not the surface mesher's
/// choice but the CAD's (a short CAD edge, a narrow face).
inline constexpr double kLocalSliverRatio = 0.05;
/// A cap flip may turn the normal of the triangle it splits by at most this (degrees).
inline constexpr double kCapFlipTurnDeg = 30.0;
inline constexpr int kMaxSliverPasses = 32;

struct SurfaceSliverStats {
  int nodesMerged = 0;
  int capsFlipped = 0;
  std::vector<int> facesChanged;  ///< 0-based model faces whose triangles changed, ascending
};

/// `model` (optional) gives the CAD surfaces for the fidelity test of cap flips inside a face
/// (left out when the mesh's nodes name entities the model lacks). Nodes from index
/// `keepFrom` on (when >= 0) are never removed by a merge: the boundary splits of the volume
/// mesher's recovery, which a merge would undo, so that the same entity went missing again.
SurfaceSliverStats mendSurfaceSlivers(SurfaceMesh& mesh, double tolerance, const Model* model = nullptr,
                                      int keepFrom = -1);

/// Number of caps (an angle above kCapAngleDeg) among the mesh's triangles.
int countSurfaceCaps(const SurfaceMesh& mesh);

}  // namespace aniso
