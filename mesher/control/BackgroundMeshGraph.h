#pragma once
// BackgroundMeshGraph — the vertex–edge graph of a background mesh (thesis sec. 3.4) and
// the two procedures that only need that graph, shared by BackgroundMesh2d and
// BackgroundMesh3d:
//   extrapolateLayers     metric for control vertices that got none from the point
//                         sources (the box corners of the kernel, sec. 3.4.1 with the
//                         extrapolation of 3.3.1 step 3): layer by layer, every unknown
//                         vertex next to a known one takes the inverse-distance weighted
//                         average (eq. 2.18, n-point form) of its known neighbours;
//   smoothByEdgeMarking   global gradation smoothing of sec. 3.4.4: all edges start
//                         unchecked; each unchecked edge is checked with the pair
//                         smoothing of sec. 2.3.4 (MetricGradation.h); when a vertex
//                         changes, all its edges become unchecked again; ends when every
//                         edge is checked.
// Edges are unique vertex pairs (a < b); per edge the caller gives its vector d = P_b − P_a
// in the space the tensors act on (S^R in 2D: M_p at the midpoint times the parametric
// vector, eq. 2.13; physical space in 3D) and its length there.
#include <array>
#include <cstdint>
#include <vector>

#include "mesher/metric/Metric.h"

namespace aniso {

struct VertexGraph {
  std::vector<std::array<int, 2>> edges;  ///< unique, a < b, sorted
  std::vector<int> start;                 ///< CSR over vertices: incident edges of v are
  std::vector<int> incident;              ///< incident[start[v] .. start[v+1])
  int other(int e, int v) const { return edges[e][0] == v ? edges[e][1] : edges[e][0]; }
  std::size_t vertexCount() const { return start.empty() ? 0 : start.size() - 1; }
};

/// Sorts and deduplicates `pairs` (each given as (a, b), any order, a ≠ b) and builds the
/// CSR incidence for `vertexCount` vertices.
VertexGraph makeVertexGraph(int vertexCount, std::vector<std::array<int, 2>> pairs);

/// Gives every vertex with known[v] == 0 a metric by layers (see above) and sets known.
/// `edgeLength[e]` > 0 is the length of edge e. Throws MeshingError when some vertex is
/// not connected to any known one.
template <int D>
void extrapolateLayers(const VertexGraph& g, const std::vector<double>& edgeLength, std::vector<std::uint8_t>& known,
                       std::vector<Metric<D>>& metric);

/// Sec. 3.4.4 with ratio gamma (≥ 1). `edgeVector[e]` is d of edge e. Sets changed[v] = 1
/// for every vertex whose metric changed (the caller refreshes what it derives from the
/// metric). Returns the number of rounds: round 1 checks every edge, round k the edges
/// unchecked again during round k − 1; a graded field takes 1 round. Throws MeshingError
/// for an invalid gamma or when it does not converge in kMaxSmoothingRounds rounds.
template <int D>
int smoothByEdgeMarking(const VertexGraph& g, const std::vector<Eigen::Matrix<double, D, 1>>& edgeVector,
                        double gamma, std::vector<Metric<D>>& metric, std::vector<std::uint8_t>& changed);

inline constexpr int kMaxSmoothingRounds = 100000;

extern template void extrapolateLayers<2>(const VertexGraph&, const std::vector<double>&,
                                          std::vector<std::uint8_t>&, std::vector<Metric<2>>&);
extern template void extrapolateLayers<3>(const VertexGraph&, const std::vector<double>&,
                                          std::vector<std::uint8_t>&, std::vector<Metric<3>>&);
extern template int smoothByEdgeMarking<2>(const VertexGraph&, const std::vector<Vec2>&, double,
                                           std::vector<Metric<2>>&, std::vector<std::uint8_t>&);
extern template int smoothByEdgeMarking<3>(const VertexGraph&, const std::vector<Vec3>&, double,
                                           std::vector<Metric<3>>&, std::vector<std::uint8_t>&);

}  // namespace aniso
