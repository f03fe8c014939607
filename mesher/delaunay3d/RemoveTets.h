#pragma once
// Removal of tetrahedra from the kernel's mesh: the tets touching the enclosing box
// corners once all points are in (thesis sec. 5.3), or the outside of a domain after
// boundary recovery (sec. 5.4, "the unmarked tetrahedra are removed").
#include <span>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

/// The live tets having at least one vertex among `vertices` (each listed once, in slot
/// order).
std::vector<TetId> tetsTouching(const TetMesh& mesh, std::span<const VertexId> vertices);

/// Frees the given live tets (duplicates allowed). Faces of surviving tets that were
/// shared with them become hull faces (no neighbour; their constrained bits stay).
/// Vertex→tet references are moved to a surviving tet, or cleared for vertices left in no
/// tet. The hull may become non-convex: Inserter then reports Outside for points the walk
/// cannot reach.
void removeTets(TetMesh& mesh, std::span<const TetId> tets);

}  // namespace aniso::del3d
