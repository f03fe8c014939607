#pragma once
// The parity rule of the merging conversion (thesis 4.7.2, fig. 4.12(c)): an all-quad
// result needs every front cycle even, i.e. every edge-connected component of the
// unconverted region (the live triangles) made of an even number of triangles (3T = 2E_i +
// E_front, so T ≡ E_front mod 2).
//
// mergeKeepsParity(mesh, t1, t2, quadVertices): would converting the two adjacent triangles
// t1, t2 into a quad leave only even components? Removing them can split their component
// only where the new quad touches the old front away from its base edge, so the check is
// free unless one of the quad's other vertices is `onFront` (a boundary vertex or a corner
// of a quad). Otherwise the pieces are explored by a breadth-first search from each
// neighbour of the pair, interleaved so that the cost is that of the smaller pieces: the
// search stops when at most one piece is still growing, and the finished pieces must be
// even (all may finish: then at most one may be odd, and only if their total is odd — the
// component was already odd, from an earlier forced merge).
#include <span>
#include <vector>

#include "mesher/quad/QuadMesh2d.h"

namespace aniso::quad {

class RegionParity {
 public:
  /// True when the merge of triangles t1 and t2 keeps every region component even (or the
  /// search exceeded maxVisits, in which case the merge is allowed).
  bool mergeKeepsParity(const QuadMesh2d& mesh, int t1, int t2, int maxVisits = 200000);
  /// The same for removing any set of live triangles (a morphed quad's, MorphStep.h); the
  /// region then loses their count, so with an odd set the pieces' total is odd.
  bool removalKeepsParity(const QuadMesh2d& mesh, std::span<const int> removed, int maxVisits = 200000);

 private:
  int find(int g);
  std::vector<int> mark_, label_;
  int epoch_ = 0;
  std::vector<int> parent_;
};

}  // namespace aniso::quad
