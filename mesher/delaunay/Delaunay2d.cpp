#include "mesher/delaunay/Delaunay2d.h"

#include <numeric>

#include "mesher/core/Error.h"
#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/SpatialSort.h"

namespace aniso::del2d {

Triangulation2d triangulatePoints(std::span<const Vec2> points, const TriangulateOptions& options,
                                  TriangulateResult* result) {
  TriangulateResult local;
  TriangulateResult& res = result != nullptr ? *result : local;
  res = TriangulateResult{};
  res.vertexOf.assign(points.size(), VertexId());
  Box2 bounds;
  for (const Vec2& p : points)
    if (p.allFinite()) bounds.add(p);
  if (bounds.empty()) throw MeshingError("triangulatePoints: no finite point");
  Triangulation2dOptions topt = options.triangulation;
  topt.transform = options.transform;
  Triangulation2d tri(bounds, topt);
  tri.reserve(points.size() + 4, 2 * points.size() + 2);
  std::vector<std::uint32_t> order;
  if (options.spatialSort) {
    order = brioOrder(points, options.sortSeed);
  } else {
    order.resize(points.size());
    std::iota(order.begin(), order.end(), 0u);
  }
  for (std::uint32_t k : order) {
    const Vec2& p = points[k];
    if (!p.allFinite()) {
      ++res.nonFinite;
      continue;
    }
    const TriId start = options.walkStart == WalkStart::LastTriangle ? tri.lastTriangle() : TriId();
    const InsertResult r = insertPoint(tri, p, options.transform, start);
    res.walkSteps += r.walkSteps;
    res.incircleTests += r.incircleTests;
    switch (r.status) {
      case InsertStatus::Inserted: ++res.inserted; res.vertexOf[k] = r.vertex; break;
      case InsertStatus::Duplicate: ++res.duplicates; res.vertexOf[k] = r.vertex; break;
      case InsertStatus::Outside:
      case InsertStatus::Refused: ++res.refused; break;
    }
  }
  return tri;
}

}  // namespace aniso::del2d
