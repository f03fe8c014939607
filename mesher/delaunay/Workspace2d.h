#pragma once
// Scratch buffers of the 2D operators (internal): owned by Triangulation2d and reused by
// every call so that the hot operators (location, insertion) do not allocate once the
// buffers have grown. Their contents are meaningless between calls.
#include <cstdint>
#include <vector>

#include "mesher/delaunay/Handles.h"

namespace aniso::del2d {

/// An edge of the boundary of a Bowyer–Watson cavity, oriented counter-clockwise around
/// the cavity: a→b with the cavity triangle `owner` on its left.
struct CavityEdge {
  VertexId a, b;
  TriId owner;       ///< cavity triangle having the edge (local index ownerEdge)
  TriId outside;     ///< triangle across the edge (invalid on the triangulation boundary)
  int ownerEdge = 0;
  int outsideEdge = -1;  ///< local index of the edge in `outside`
  bool constrained = false;
};

struct Workspace2d {
  std::vector<TriId> cavity;            ///< triangles of the current cavity
  std::vector<TriId> stack;             ///< DFS stack
  std::vector<CavityEdge> boundary;     ///< boundary of the cavity
  std::vector<TriId> tested;            ///< triangles marked "tested, not in the cavity"
  std::vector<TriId> created;           ///< triangles made by the last operation
  std::vector<std::uint32_t> startOf;   ///< per vertex: new triangle whose edge starts there
  std::vector<std::uint32_t> vstamp;    ///< per vertex: stamp of the last visit
  std::uint32_t stamp = 0;              ///< current stamp for vstamp
  std::uint64_t rng = 0x9E3779B97F4A7C15ull;  ///< state of the stochastic walk

  /// xorshift64: cheap deterministic pseudo-random numbers for the walk.
  std::uint32_t nextRandom() {
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return static_cast<std::uint32_t>(rng >> 32);
  }
};

}  // namespace aniso::del2d
