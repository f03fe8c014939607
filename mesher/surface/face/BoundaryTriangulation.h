#pragma once
// Triangulation of the boundary nodes of a face (thesis sec. 4.4, first phase): the initial
// two triangles over the boundary's (u, v) box (Triangulation2d), then every boundary node
// inserted by Bowyer–Watson (del2d::insertPoint) with the in-circle test in the metric
// M = M_s M_p of the inserted node itself (sec. 4.2.1: "for each inserted node local metric
// is retrieved from CS once"), in a randomised, spatially coherent order: a fixed-seed
// shuffle in rounds, each sorted along a Hilbert curve (del2d::brioOrder), the walk starting
// at the last created triangle. Deterministic for a given seed.
//
// FlatBoundary is the face's loops concatenated (node k of the concatenation is boundary
// vertex k of the FaceMesh): every node is a distinct vertex in (u, v), also where the same
// global node appears twice (seam) or consecutively (pole).
//
// Two boundary nodes at the same (u, v) with the same global node (loops touching at a
// vertex) share one vertex of the triangulation.
// Problems reported (the triangulation is then unusable for meshing; nothing throws):
//   • two different global nodes at the same (u, v);
//   • a node the kernel refuses even with the identity metric (should not happen).
#include <cstdint>
#include <string>
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/surface/FaceBoundary.h"

namespace aniso::face {

struct FlatBoundary {
  std::vector<Vec2> uv;
  std::vector<int> node;                   ///< global node of each boundary vertex
  std::vector<Vec3> at;                    ///< BoundaryNode::at of each (NaN: p(uv))
  std::vector<std::uint32_t> loopBegin;    ///< loop l is [loopBegin[l], loopBegin[l+1])
  std::vector<std::uint32_t> next;         ///< the following node in the same loop

  std::size_t size() const { return uv.size(); }
  /// "node 12 (u, v) = (0.5, 1)" for messages.
  std::string describe(std::uint32_t k) const;
};

/// Concatenates the loops. Throws MeshingError for an empty boundary, a loop with fewer
/// than 2 nodes or a non-finite (u, v) (invalid input, FaceMesher.h contract).
FlatBoundary flattenBoundary(const FaceBoundary& boundary);

struct BoundaryTriangulation {
  del2d::Triangulation2d tri;
  std::vector<del2d::VertexId> vertexOf;  ///< per boundary node; invalid where refused
  std::vector<std::string> problems;
};

/// innerAngles: each node splits its containing triangle and the inner-angles criterion
/// (sec. 4.2.2) swaps edges afterwards (at most 50 swaps per node, Table 4.1) instead of the
/// Bowyer–Watson cavity.
BoundaryTriangulation triangulateBoundary(const FlatBoundary& boundary, const ControlSpace2d& cs,
                                          std::uint64_t seed, bool innerAngles = false);

}  // namespace aniso::face
