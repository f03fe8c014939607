#pragma once
// Edge flip T32 (thesis sec. 5.2.2, Fig. 5.2, "flip(E)"): the three tetrahedra around an
// edge (a, b) with ring vertices c0, c1, c2 become the two tetrahedra sharing the face
// (c0, c1, c2). The inverse of T23. Check, then change.
#include <array>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

struct Flip32Plan {
  std::array<TetId, 3> oldTets;
  std::array<std::array<VertexId, 4>, 2> newTets;
};

/// True when the edge joining local vertices i and j (i != j) of the live tet t can be
/// flipped: exactly three tets around it (closed ring), none of the three faces around
/// the edge constrained, both new tets positively oriented (the edge pierces the
/// interior of triangle c0 c1 c2). Fills *plan when given.
bool canFlip32(const TetMesh& mesh, TetId t, int i, int j, Flip32Plan* plan = nullptr);

/// Applies a plan from canFlip32 (mesh unchanged since). Returns the two new tets.
std::array<TetId, 2> flip32(TetMesh& mesh, const Flip32Plan& plan);

}  // namespace aniso::del3d
