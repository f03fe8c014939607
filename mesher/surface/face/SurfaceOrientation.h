#pragma once
// foldedTriangles — the fold validator of a face mesh (called by the tests after meshFace):
// the triangles that are not upright on the face's surface by the fold guard's own test
// (SurfaceLift::upright: chord normal within 75° of the corner normals, for triangles
// small against the curvature), except those collapsing at a pole (two corners the same
// global node: the assembly drops them).
#include <array>
#include <vector>

#include "mesher/geometry/ParametricSurface.h"
#include "mesher/surface/FaceBoundary.h"

namespace aniso::face {

/// True if two corners of the triangle are the same global node (consecutive boundary
/// nodes of a degenerate edge, a pole): the assembly drops such a triangle, it has no area.
bool collapsesAtPole(const FaceMesh& mesh, const std::array<int, 3>& v);

/// The triangles of `mesh` (in the (u, v) of surface s) that are not upright, in index order.
std::vector<int> foldedTriangles(const FaceMesh& mesh, const ParametricSurface& s);

}  // namespace aniso::face
