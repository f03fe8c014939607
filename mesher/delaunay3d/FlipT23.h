#pragma once
// Face flip T23 (thesis sec. 5.2.2, Fig. 5.2, "flip(F)"): the two tetrahedra sharing face
// (a, b, c), with apexes d and e, become the three tetrahedra around the new edge (d, e).
// Check, then change (STYLE.md §6): canFlip23 decides legality and returns a plan;
// flip23 applies it.
#include <array>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

struct Flip23Plan {
  std::array<TetId, 2> oldTets;
  std::array<std::array<VertexId, 4>, 3> newTets;
};

/// True when face `face` of the live tet t can be flipped: it has a neighbour, it is not
/// constrained, and the three new tets are positively oriented (exact orient3d), i.e. the
/// segment (d, e) crosses the interior of triangle (a, b, c). Fills *plan when given.
bool canFlip23(const TetMesh& mesh, TetId t, int face, Flip23Plan* plan = nullptr);

/// Applies a plan from canFlip23 (the mesh must not have changed since). Returns the
/// three new tets; outer faces keep neighbours and constrained bits.
std::array<TetId, 3> flip23(TetMesh& mesh, const Flip23Plan& plan);

}  // namespace aniso::del3d
