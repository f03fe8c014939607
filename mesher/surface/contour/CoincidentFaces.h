#pragma once
// CoincidentFaces — two CAD faces that are one surface region (same boundary nodes, each
// lying on the other's surface), meshed once: the later face takes the earlier one's
// triangles (thesis 4.1: one discretization of each piece of the surface, shared by the
// blocks it bounds).
//
// Exported assemblies hold such pairs where a boolean leaves a slit (a solid touching
// itself across a face: two faces, opposite orientations, both in its shell) or where two
// parts touch without being fused. Meshed separately, the pairs give coincident but
// distinct nodes: the volume mesher cannot insert them, and the parts are not conformal.
// Shared, the slit becomes internal to the solid (BoundaryMesh cancels the pair) and the
// touching parts become conformal.
//
// g is the twin of f < g when both meshed, with the same set of boundary nodes (their
// loops were discretized on the same nodes: CoincidentEdges.h), and the surface point at
// the (u,v) centroid of each of up to kSamples triangles of either face lies within
// max(tol_f, tol_g) of the other face's surface (the trimmed regions then coincide: the
// same boundary on one surface). Not applied to quad meshes.
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/surface/FaceBoundary.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso::contour {

/// twin[g] = f (f < g) or −1. `meshes[f]` null for faces not meshed.
std::vector<int> coincidentFaces(const Model& model, const std::vector<const FaceMesh*>& meshes);

/// The triangles [first, last) of `mesh` (those of the twin), added again for face `to`,
/// flipped when `to`'s oriented normal (from its own face mesh `toMesh`) is opposite.
/// Returns the number added.
int shareFaceTriangles(const Model& model, int to, std::size_t first, std::size_t last, const FaceMesh& toMesh,
                       SurfaceMesh& mesh);

}  // namespace aniso::contour
