#pragma once
// The initial mesh of thesis sec. 5.3, step 2: the bounding box of the points, enlarged by
// a margin and triangulated, so that every point to insert lies strictly inside. The tets
// touching the 8 corners are removed afterwards with tetsTouching + removeTets
// (RemoveTets.h) once all points are in.
//
// Bowyer–Watson keeps a mesh Delaunay only if it starts Delaunay, in the metric of the
// in-sphere test. So the box is built in metric space: an axis-aligned box around M·bounds
// whose corners are pushed outward by slightly different amounts (no five corners are
// cospherical, so the Delaunay triangulation of the corners is unique), mapped back by
// M⁻¹; the corners are then triangulated by brute force with the same exact predicates,
// on the same transformed coordinates (TransformPoint.h), as the insertion. In physical
// space the box is a slightly irregular parallelepiped (a hexahedron when M = I).
#include <array>

#include "mesher/core/Types.h"
#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

struct EnclosingBox {
  std::array<VertexId, 8> corners;  ///< corner c: at the (bit0: x, bit1: y, bit2: z) side in metric space
  Box3 box;                         ///< physical bounding box of the corners
};

/// Appends the 8 corners and the Delaunay tets of their convex hull (5 or 6) to a mesh
/// that has no tets yet. In metric space the box is M·bounds' bounding box grown on every
/// side by at least margin × max(largest side, 1e-3 × (1 + largest |coordinate|)), so it
/// has volume even for flat or single-point bounds. `transform`: the M of the in-sphere
/// tests that will follow (nullptr = identity). Throws MeshingError if the mesh has
/// tets, bounds is empty or not finite, margin is not > 0 or M is not invertible with
/// det M > 0.
EnclosingBox createEnclosingBox(TetMesh& mesh, const Box3& bounds, double margin = 0.1,
                                const Mat3* transform = nullptr);

}  // namespace aniso::del3d
