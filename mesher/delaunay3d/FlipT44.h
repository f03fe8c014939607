#pragma once
// Edge flip T44 (thesis sec. 5.2.2, the edge flip "extended to cases with more than three
// tetrahedra incident to an edge"): the four tetrahedra around an edge (a, b) with ring
// vertices c0..c3 form an octahedron; it is retriangulated around the diagonal (c0, c2)
// or (c1, c3) into four new tetrahedra. Typical use: c's coplanar with a, b (where
// T23/T32 cannot act), but it is legal whenever the four new tets are positive.
// Check, then change.
#include <array>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

struct Flip44Plan {
  std::array<TetId, 4> oldTets;
  std::array<std::array<VertexId, 4>, 4> newTets;
};

/// True when the edge joining local vertices i and j of the live tet t has exactly four
/// tets around it (closed ring, ring vertices c0..c3 in rotational order starting in t),
/// none of the four faces around the edge is constrained, and the four tets around the
/// new edge (c_s, c_{s+2}), s = `diagonal` (0 or 1), are positively oriented.
bool canFlip44(const TetMesh& mesh, TetId t, int i, int j, int diagonal, Flip44Plan* plan = nullptr);

/// Applies a plan from canFlip44 (mesh unchanged since). Returns the four new tets.
std::array<TetId, 4> flip44(TetMesh& mesh, const Flip44Plan& plan);

}  // namespace aniso::del3d
