#pragma once
// validate() — the checker that tests call after every operator (STYLE.md §9; geogram's
// check_combinatorics / check_geometry).
#include <cstddef>
#include <string>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

struct ValidateOptions {
  bool checkOrientation = true;  ///< every live tet has orient3d > 0 (exact)
  /// Empty-circumsphere test for every interior, non-constrained face: the vertex opposite
  /// across the face is not strictly inside the circumsphere of the tet (exact insphere on
  /// the points M·x, with their orientation sign). Valid for a constant transformation M.
  bool checkDelaunay = false;
  Mat3 transform = Mat3::Identity();
  std::size_t maxProblems = 20;  ///< stop collecting after this many
};

/// Checks the mesh and returns one string per problem found (empty: valid):
/// - free list: every slot on it is marked free, no cycle, free + live = slots, and every
///   slot marked free is on it;
/// - each live tet: 4 distinct existing vertices; no scratch mark left set;
/// - adjacency symmetry: the neighbour across face i is live, points back at (t, i) and
///   shares the same 3 vertices; the constrained bit is equal on both sides;
/// - vertex→tet: a vertex's tet, if any, is live and contains it; a vertex used by a live
///   tet has one;
/// - orientation and (optionally) the Delaunay property, see ValidateOptions.
std::vector<std::string> validate(const TetMesh& mesh, const ValidateOptions& options = {});

}  // namespace aniso::del3d
