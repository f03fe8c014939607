#pragma once
// validate — the invariants of a Triangulation2d, called by the tests after every operator
// (STYLE.md §9; geogram check_combinatorics/check_geometry). Returns human-readable
// problems naming the offending triangles and vertices; empty means valid.
//
// Always checked:
//   • every live triangle has three distinct existing vertices and is counter-clockwise
//     (exact orient2d > 0);
//   • adjacency is symmetric and a neighbour shares exactly the edge (reversed), with the
//     same constrained bit on both sides; no triangle is its own neighbour;
//   • every directed edge occurs in at most one triangle (no overlap along edges);
//   • the free list holds exactly the free slots, without cycles; scratch marks are 0;
//   • every vertex used by a live triangle links to a live triangle containing it, and
//     a vertex linked to a triangle is in it.
// Optionally (delaunay = true): for every unconstrained interior edge, the opposite
// vertex of the neighbour is not strictly inside the circumcircle, evaluated on the
// transformed coordinates M·x with the exact predicate (PlaneTransform, the same
// evaluation as the insertion's), for one constant M.
#include <cstddef>
#include <string>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/delaunay/Triangulation2d.h"

namespace aniso::del2d {

struct ValidateOptions {
  bool delaunay = false;
  Mat2 transform = Mat2::Identity();
  std::size_t maxProblems = 50;  ///< stop collecting after this many
};

std::vector<std::string> validate(const Triangulation2d& tri, const ValidateOptions& options = {});

}  // namespace aniso::del2d
