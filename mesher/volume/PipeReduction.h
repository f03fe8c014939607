#pragma once
// PIPE-REDUCTION (thesis sec. 5.4.1, table 5.3): recovers a missing boundary edge or face
// by flips alone — T23 on a crossing face, T32 / T44 / general edge removal (EdgeRemoval.h)
// on a crossing edge. Each flip is checked first (exact orientation, constrained faces,
// protected boundary edges), applied tentatively, and kept only if it lowers the pipe's
// weight (Pipe::weight); otherwise it is undone. When no single flip helps, a face flip
// followed by an edge removal is tried (two-step lookahead). The weight strictly decreases
// with every kept change, so the process ends; `maxChanges` bounds it further, and so does
// a budget of trials per entity (PipeReduction.cpp: kMaxTrialsPerEntity).
#include <cstdint>
#include <functional>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::volume {

struct FlipCounters {
  std::uint64_t flips23 = 0, removals = 0, tried = 0;
};

/// True for an edge that must not be removed (a boundary edge present in the mesh).
using EdgeGuard = std::function<bool(del3d::VertexId, del3d::VertexId)>;

/// Makes edge (a, b) present if flips can. Returns true when the edge is present.
bool reduceEdgePipe(del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b, const EdgeGuard& guard,
                    int maxChanges, FlipCounters& counters);

/// Makes face (a, b, c) present if flips can; its three edges must be present. Returns
/// true when the face is present.
bool reduceFacePipe(del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b, del3d::VertexId c,
                    const EdgeGuard& guard, int maxChanges, FlipCounters& counters);

}  // namespace aniso::volume
