#pragma once
// buildDelaunay — the whole unconstrained triangulation of a point set (thesis sec. 5.3,
// Alg. 5.2 with q_Bt = 0): enclosing box (EnclosingBox.h), BRIO + Hilbert insertion order
// (SpatialSort.h), location by walk from the last created tet or from SeedOctree, and
// Bowyer–Watson insertion (Inserter.h) with the in-sphere test on M·x.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/delaunay3d/EnclosingBox.h"
#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

struct DelaunayOptions {
  bool spatialSort = true;       ///< BRIO + Hilbert order; false: the input order
  std::uint64_t sortSeed = 0x5EEDu;
  bool useSeedOctree = false;    ///< start walks from SeedOctree (thesis 5.3.2) instead of the last tet
  std::uint32_t octreeLeafThreshold = 1000;
  double boxMargin = 0.1;        ///< see createEnclosingBox
  Mat3 transform = Mat3::Identity();  ///< constant M of the in-sphere test (det M > 0)
  bool removeBox = false;        ///< remove the tets touching the box corners at the end
  bool reserve = true;           ///< reserve the arrays for 7 tets per point (uniform random: ~6.75)
};

struct DelaunayResult {
  EnclosingBox box;
  /// Per input point: its vertex (new, or the equal earlier one for a duplicate); invalid
  /// for a refused or non-finite point.
  std::vector<VertexId> vertexOf;
  std::size_t inserted = 0, duplicates = 0, refused = 0, nonFinite = 0;
};

/// Triangulates `points` into `mesh`, which must be empty (it is cleared). The box corners
/// are the vertices 0..7, input points follow in insertion order. Without removeBox the
/// result covers the enlarged box and (for the identity, or a constant M on exact
/// transformed coordinates) is Delaunay. Throws MeshingError when no point is finite.
DelaunayResult buildDelaunay(TetMesh& mesh, std::span<const Vec3> points, const DelaunayOptions& options = {});

}  // namespace aniso::del3d
