#pragma once
// Improvement of a face triangulation (thesis sec. 4.6, alg. 4.2), in the face's metric.
// Each pass (N_imp passes, default 2):
//   - mixed metric Laplace smoothing (4.6.1, eq. 4.2–4.3): each free vertex moved towards
//     the average of its neighbours measured in metric space (the plain average where the
//     metric gradation is low, the metric version where it is high), never inverting an
//     adjacent triangle (the move is shortened or cancelled: check, then change);
//   - topological swap (4.6.2) in areas of low metric gradation: flip an edge when it
//     brings the vertex degrees closer to 6;
//   - geometric swap (4.6.3): flip an edge when the inner-angles criterion in metric space
//     prefers the other diagonal;
//   - postprocessing (4.6.4) of the worst triangles.
// Constrained edges (the face boundary) are never flipped; vertices flagged fixed (the
// boundary vertices) never move. The result is a valid triangulation (every triangle
// counter-clockwise in (u, v)).
#include <cstdint>
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/delaunay/Triangulation2d.h"

namespace aniso {

struct ImproveOptions {
  int passes = 2;               ///< N_imp
  int smoothingIterations = 2;  ///< Laplace sweeps per pass
  bool topologicalSwap = true;
  bool geometricSwap = true;
};

struct ImproveStats {
  long long moves = 0, topologicalSwaps = 0, geometricSwaps = 0;
};

/// `fixed[v]` true for vertices that must not move (boundary); vertices not referenced by
/// any live triangle are ignored.
ImproveStats improveFaceMesh(del2d::Triangulation2d& tri, const ControlSpace2d& cs,
                             const std::vector<std::uint8_t>& fixed, const ImproveOptions& options = {});

}  // namespace aniso
