#pragma once
// Vertex -> tet incidence of a TetMesh in compressed rows (sec. 5.6: smoothing works on
// vertex stars): row v lists the live tets containing vertex v, in slot order. Built in
// two passes over the tets (count, fill), 4 entries per tet. A snapshot: valid while the
// mesh's topology does not change (moving vertices keeps it valid; flips and insertions do
// not). Cheaper than a star walk per vertex when every vertex's star is needed once.
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::improve3d {

class VertexTets {
 public:
  explicit VertexTets(const del3d::TetMesh& mesh);
  /// The live tets containing v (slot indices, ascending).
  std::span<const std::uint32_t> of(del3d::VertexId v) const {
    return {tets_.data() + first_[v.index], tets_.data() + first_[v.index + 1]};
  }
  std::size_t numVertices() const { return first_.size() - 1; }

 private:
  std::vector<std::uint32_t> first_;  ///< numVertices + 1 row starts
  std::vector<std::uint32_t> tets_;
};

}  // namespace aniso::improve3d
