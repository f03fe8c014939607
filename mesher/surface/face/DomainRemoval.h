#pragma once
// Removal of the triangles outside the face (thesis sec. 4.4: "All elements directly
// adjacent to boundary contours are marked as valid, using the input geometry
// specification. The adjacency information is then used to propagate the marking …
// avoiding trespassing of contours … all unmarked elements can be safely removed"):
// del2d::markDomain from the oriented loop edges (the face on the left of every edge:
// outer loops counter-clockwise, holes clockwise, FaceBoundary.h), then
// del2d::removeTriangles of everything unmarked — the box triangles and the holes.
// Seams and poles need nothing special: in (u, v) they are ordinary polygon sides.
//
// Check, then change: nothing is removed when the marking shows that the loops do not
// bound a region consistently, reported as problems:
//   • a loop edge missing from the triangulation (recovery failed before);
//   • the marking reached the right side of a loop edge (wrong orientation, a hole outside
//     the outer loop, crossing loops);
//   • the marking reached a box corner (the face would be unbounded: an outer loop given
//     clockwise);
//   • nothing was marked.
#include <cstddef>
#include <string>
#include <vector>

#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/surface/face/BoundaryTriangulation.h"

namespace aniso::face {

/// Returns the problems (empty: the outside was removed). `removed` (may be null) receives
/// the number of triangles removed.
std::vector<std::string> removeOutside(del2d::Triangulation2d& tri, const FlatBoundary& boundary,
                                       const std::vector<del2d::VertexId>& vertexOf, std::size_t* removed = nullptr);

}  // namespace aniso::face
