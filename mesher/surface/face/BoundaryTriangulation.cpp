#include "mesher/surface/face/BoundaryTriangulation.h"

#include <sstream>

#include "mesher/core/Error.h"
#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/PlaneTransform.h"
#include "mesher/delaunay/SpatialSort.h"
#include "mesher/delaunay/Workspace2d.h"
#include "mesher/surface/face/FaceMetric.h"
#include "mesher/surface/face/InnerAngleSwaps.h"

namespace aniso::face {

using namespace del2d;

std::string FlatBoundary::describe(std::uint32_t k) const {
  std::ostringstream s;
  s.precision(17);
  s << "node " << node[k] << " (u, v) = (" << uv[k].x() << ", " << uv[k].y() << ")";
  return s.str();
}

FlatBoundary flattenBoundary(const FaceBoundary& boundary) {
  if (boundary.loops.empty()) throw MeshingError("face " + std::to_string(boundary.face + 1) + ": no boundary loop");
  FlatBoundary f;
  std::size_t total = 0;
  for (const auto& loop : boundary.loops) total += loop.size();
  f.uv.reserve(total);
  f.node.reserve(total);
  f.next.reserve(total);
  for (std::size_t l = 0; l < boundary.loops.size(); ++l) {
    const auto& loop = boundary.loops[l];
    if (loop.size() < 2)
      throw MeshingError("face " + std::to_string(boundary.face + 1) + ": boundary loop " + std::to_string(l + 1) +
                         " has fewer than 2 nodes");
    const auto begin = static_cast<std::uint32_t>(f.uv.size());
    f.loopBegin.push_back(begin);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      if (!loop[i].uv.allFinite())
        throw MeshingError("face " + std::to_string(boundary.face + 1) + ": boundary node " +
                           std::to_string(loop[i].node) + " has a non-finite (u, v)");
      f.uv.push_back(loop[i].uv);
      f.node.push_back(loop[i].node);
      f.at.push_back(loop[i].at);
      f.next.push_back(i + 1 < loop.size() ? static_cast<std::uint32_t>(f.uv.size()) : begin);
    }
  }
  f.loopBegin.push_back(static_cast<std::uint32_t>(f.uv.size()));
  return f;
}

namespace {

/// Inner-angles mode: swaps per inserted node (Table 4.1).
constexpr std::size_t kMaxSwapsPerNode = 50;

Box2 boundsOf(const std::vector<Vec2>& pts) {
  Box2 b;
  for (const Vec2& p : pts) b.add(p);
  return b;
}

}  // namespace

BoundaryTriangulation triangulateBoundary(const FlatBoundary& boundary, const ControlSpace2d& cs,
                                          std::uint64_t seed, bool innerAngles) {
  const Box2 box = boundsOf(boundary.uv);
  Triangulation2dOptions topt;
  topt.transform = metricAt(cs, 0.5 * (box.lo + box.hi));
  if (PlaneTransform(topt.transform).orientation() == 0) topt.transform = Mat2::Identity();
  BoundaryTriangulation out{Triangulation2d(box, topt), {}, {}};
  Triangulation2d& tri = out.tri;
  const std::size_t n = boundary.size();
  tri.reserve(n + 4, 2 * n + 2);
  out.vertexOf.assign(n, VertexId());
  // Which boundary node made each vertex (to name both nodes of a duplicate).
  std::vector<std::uint32_t> nodeOfVertex(n + 4, kNone);
  std::vector<TriId> created;
  for (std::uint32_t k : brioOrder(boundary.uv, seed)) {
    const Vec2& p = boundary.uv[k];
    Mat2 m = metricAt(cs, p);
    InsertPlan plan = innerAngles ? planInsertion(tri, p, innerAnglesConflict(), tri.lastTriangle())
                                  : planInsertion(tri, p, m, tri.lastTriangle());
    if (plan.status == InsertStatus::Refused) {
      m = Mat2::Identity();
      plan = planInsertion(tri, p, m, TriId());
    }
    const InsertResult r = applyInsertion(tri, plan);
    if (r.status == InsertStatus::Inserted) {
      out.vertexOf[k] = r.vertex;
      nodeOfVertex[r.vertex.index] = k;
      const PlaneTransform tr(m);
      if (innerAngles && tr.orientation() != 0) {
        created.assign(tri.workspace().created.begin(), tri.workspace().created.end());
        restoreDelaunay(tri, created, tr, FlipCriterion::InnerAngles, kMaxSwapsPerNode);
      }
    } else if (r.status == InsertStatus::Duplicate) {
      const std::uint32_t other = r.vertex.index < nodeOfVertex.size() ? nodeOfVertex[r.vertex.index] : kNone;
      if (other != kNone && boundary.node[other] == boundary.node[k]) {
        // The same global node twice at the same (u, v): the loops touch at a vertex (an
        // inner loop touching the outer one on a seam, a pinched loop). One vertex serves both.
        out.vertexOf[k] = r.vertex;
        continue;
      }
      out.problems.push_back("boundary " + boundary.describe(k) + " coincides with " +
                             (other != kNone ? boundary.describe(other) : std::string("a box corner")) +
                             " in (u, v)");
    } else {
      out.problems.push_back("boundary " + boundary.describe(k) + " could not be inserted");
    }
  }
  return out;
}

}  // namespace aniso::face
