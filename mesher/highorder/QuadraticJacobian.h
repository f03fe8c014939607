#pragma once
// Jacobian determinants of quadratic elements at their corners and centroid: the validity
// measure of Order2.h. Corners in the linear element's order; mid nodes as the meshes store
// them (VolumeMesh::kTetEdges for tetrahedra, edge (k, k+1) for triangles and quads).
//
// Each function returns the smallest determinant over the samples divided by the straight
// element's (1 for mid nodes at the chord midpoints of a triangle or tetrahedron; ≤ 0 when
// curving inverts the element somewhere), or 0 when the straight element is degenerate.
// For triangles and quads in 3D the determinant is n · (∂x/∂ξ × ∂x/∂η) with n the unit
// normal of the straight element, so that folding over counts as inversion.
#include <array>

#include "mesher/core/Types.h"

namespace aniso {

/// 10-node tetrahedron; samples: the 4 corners and the centroid. Reference: 6 × volume.
double tet10JacobianRatio(const std::array<Vec3, 4>& corner, const std::array<Vec3, 6>& mid);

/// 6-node triangle; samples: the 3 corners and the centroid. Reference: 2 × area.
double tri6JacobianRatio(const std::array<Vec3, 3>& corner, const std::array<Vec3, 3>& mid);

/// 8-node serendipity quad on [−1, 1]²; samples: the 4 corners and the centre. Reference:
/// the straight (bilinear) quad's determinant at its centre; n from its diagonals.
double quad8JacobianRatio(const std::array<Vec3, 4>& corner, const std::array<Vec3, 4>& mid);

}  // namespace aniso
