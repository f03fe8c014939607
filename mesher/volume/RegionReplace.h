#pragma once
// replaceRegion — swaps any number of tetrahedra for another tetrahedralization of the
// same polyhedron (the "change" step of the cavity recovery, CavityRecovery.h; the flips
// use del3d::replaceTets, which is bounded to a few tets). Check, then change: the new
// set must have exactly the old set's boundary faces (each once) and every other face
// shared by exactly two new tets, or nothing is changed.
#include <array>
#include <span>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::volume {

/// Replaces the distinct live tets `oldTets` by tets with the vertex quadruples `newTets`
/// (each positively oriented — checked by the caller). Faces on the common boundary keep
/// their outer neighbours and constrained bits; inner faces are unconstrained. Vertices of
/// the old tets used by no new tet are left in no tet (vertexTet cleared). Returns false,
/// with the mesh untouched, when the boundaries do not match. Writes the new ids to *out.
bool replaceRegion(del3d::TetMesh& mesh, std::span<const del3d::TetId> oldTets,
                   std::span<const std::array<del3d::VertexId, 4>> newTets, std::vector<del3d::TetId>* out = nullptr);

}  // namespace aniso::volume
