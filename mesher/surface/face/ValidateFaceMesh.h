#pragma once
// validateFaceMesh — the invariants of a FaceMesh against the FaceBoundary it was made for
// (STYLE.md §9; called by the tests after meshFace). Empty result: valid. Checked:
//   • uv and node have the same size; the first N vertices (N = boundary nodes) are the
//     boundary nodes in loop order, same (u, v) and global node; the others have node −1;
//   • triangle indices in range and distinct; every triangle strictly counter-clockwise in
//     (u, v) (exact orient2d);
//   • every directed edge occurs in at most one triangle; an edge used once (no opposite
//     twin) is exactly a boundary edge k → next(k), and every boundary edge occurs once in
//     that direction (the mesh boundary is the given boundary, nothing split or missing);
//   • every interior vertex is used by a triangle.
// With all triangles positively oriented, a manifold edge structure and the given loops as
// its boundary, the triangles cover the face exactly once (no overlap, no crossing): the
// covering degree equals the winding number of the loops.
#include <cstddef>
#include <string>
#include <vector>

#include "mesher/surface/FaceBoundary.h"

namespace aniso::face {

std::vector<std::string> validateFaceMesh(const FaceMesh& mesh, const FaceBoundary& boundary,
                                          std::size_t maxProblems = 50);

}  // namespace aniso::face
