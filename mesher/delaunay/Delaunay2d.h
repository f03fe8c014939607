#pragma once
// triangulatePoints — the Delaunay triangulation of a point set in one call (thesis sec.
// 4.4, boundary-node triangulation before the constraining phase): initial two triangles
// over the bounds (Triangulation2d), insertion in BRIO + Hilbert order (SpatialSort.h) by
// Bowyer–Watson with a constant transformation M (InsertPoint.h), walks started from the
// seeding quadtree or from the last created triangle (PointLocation.h).
//
// The box corners are vertices 0..3; the triangulation covers the enlarged box (remove
// the triangles at the corners with DomainMarking.h when needed). Points equal to an
// earlier point map to that vertex; non-finite points are skipped.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/delaunay/Triangulation2d.h"

namespace aniso::del2d {

enum class WalkStart {
  SeedQuadtree,  ///< thesis sec. 4.4.1
  LastTriangle,  ///< the most recently created triangle (best for spatially sorted input)
};

struct TriangulateOptions {
  Triangulation2dOptions triangulation;
  bool spatialSort = true;  ///< BRIO + Hilbert; false: the input order
  std::uint64_t sortSeed = 0x5EEDu;
  WalkStart walkStart = WalkStart::LastTriangle;
  /// Constant M of the in-circle test (also used for the initial diagonal; overrides
  /// triangulation.transform).
  Mat2 transform = Mat2::Identity();
};

struct TriangulateResult {
  /// Per input point: its vertex (new, or the equal earlier one); invalid when skipped.
  std::vector<VertexId> vertexOf;
  std::size_t inserted = 0, duplicates = 0, refused = 0, nonFinite = 0;
  std::size_t walkSteps = 0, incircleTests = 0;  ///< totals (statistics)
};

/// Throws MeshingError when no point is finite.
Triangulation2d triangulatePoints(std::span<const Vec2> points, const TriangulateOptions& options = {},
                                  TriangulateResult* result = nullptr);

}  // namespace aniso::del2d
