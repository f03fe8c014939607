#pragma once
// Sharp-corner triangles — a triangle alone at a boundary corner whose angle is below
// contour::kQuadCornerAngle (asin 0.1) stays a triangle in any quad mesh: a quad there
// would have a scaled Jacobian under 0.1. The conversion (thesis 4.7) leaves it out, like
// the pole triangles (PoleTriangles.h): detached before the front starts, its inner edge
// becomes boundary, and the region left has the boundary parity the contour discretization
// gave it for all-quad (contour/CornerParity.h: a face with an odd number of such corners
// gets an odd boundary count, which this triangle takes). Reattached with
// reattachTriangles. The angle is measured in 3D when the corners have nodes, else in
// (u, v).
#include <span>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/quad/QuadMesh2d.h"

namespace aniso::quad {

/// Detaches every live triangle that is the only element at one of its boundary corners
/// and whose angle there is below kQuadCornerAngle; returns their corners. `nodes` are the
/// 3D points of the global nodes (mesh.node), empty to measure in (u, v).
std::vector<Corners> detachSharpCornerTriangles(QuadMesh2d& mesh, std::span<const Vec3> nodes);

}  // namespace aniso::quad
