#include "mesher/volume/RecoveryDiagnosis.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "mesher/volume/MeshQueries.h"
#include "mesher/volume/Pipe.h"

namespace aniso::volume {

using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

namespace {

double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

double triangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a).normalized();
  const Vec3 q = p - n.dot(p - a) * n;  // projection on the plane
  const bool inside = n.dot((b - a).cross(q - a)) >= 0 && n.dot((c - b).cross(q - b)) >= 0 &&
                      n.dot((a - c).cross(q - c)) >= 0;
  if (inside) return (p - q).norm();
  return std::min({segmentDistance(p, a, b), segmentDistance(p, b, c), segmentDistance(p, c, a)});
}

/// Counts over a pipe: crossing faces that are constrained, crossing edges that are
/// boundary edges; the nearest boundary vertex of the explored tets (not in `own`).
struct PipeSummary {
  std::size_t faces = 0, edges = 0, constrainedFaces = 0, boundaryEdges = 0;
  bool degenerate = false;
  double nearest = std::numeric_limits<double>::infinity();
};

template <class Distance>
PipeSummary summarize(const TetMesh& m, const Pipe& pipe, const std::vector<VertexId>& own,
                      const IsBoundaryVertex& boundaryVertex, const IsBoundaryEdge& boundaryEdge, Distance distance) {
  PipeSummary s;
  s.faces = pipe.faces.size();
  s.edges = pipe.edges.size();
  s.degenerate = pipe.degenerate;
  for (const FaceRef& f : pipe.faces)
    if (m.isConstrained(f.tet, f.face)) ++s.constrainedFaces;
  for (const EdgeRef& e : pipe.edges)
    if (boundaryEdge(m.vertex(e.tet, e.i), m.vertex(e.tet, e.j))) ++s.boundaryEdges;
  for (const TetId t : pipe.tets)
    for (int k = 0; k < 4; ++k) {
      const VertexId v = m.vertex(t, k);
      if (std::find(own.begin(), own.end(), v) != own.end() || !boundaryVertex(v)) continue;
      s.nearest = std::min(s.nearest, distance(m.point(v)));
    }
  return s;
}

std::string format(const char* what, double length, const PipeSummary& s) {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "%s: length %.3g, pipe %zu faces / %zu edges%s (%zu constrained faces, %zu boundary edges), "
                "nearest boundary node at %.2g lengths",
                what, length, s.faces, s.edges, s.degenerate ? " degenerate" : "", s.constrainedFaces, s.boundaryEdges,
                s.nearest / length);
  return buf;
}

}  // namespace

std::string describeMissingEdge(const TetMesh& m, VertexId a, VertexId b, const IsBoundaryVertex& boundaryVertex,
                                const IsBoundaryEdge& boundaryEdge) {
  Pipe pipe;
  segmentPipe(m, a, b, pipe);
  const Vec3 pa = m.point(a), pb = m.point(b);
  const PipeSummary s = summarize(m, pipe, {a, b}, boundaryVertex, boundaryEdge,
                                  [&](const Vec3& p) { return segmentDistance(p, pa, pb); });
  return format("edge", (pb - pa).norm(), s);
}

std::string describeMissingTriangle(const TetMesh& m, const std::array<VertexId, 3>& t,
                                    const IsBoundaryVertex& boundaryVertex, const IsBoundaryEdge& boundaryEdge) {
  const Vec3 a = m.point(t[0]), b = m.point(t[1]), c = m.point(t[2]);
  const double l = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  std::vector<TetId> star;
  int present = 0;
  for (int k = 0; k < 3; ++k) present += findEdge(m, t[k], t[(k + 1) % 3], star).valid() ? 1 : 0;
  Pipe pipe;
  if (present == 3) trianglePipe(m, t[0], t[1], t[2], pipe);
  const PipeSummary s = summarize(m, pipe, {t[0], t[1], t[2]}, boundaryVertex, boundaryEdge,
                                  [&](const Vec3& p) { return triangleDistance(p, a, b, c); });
  char buf[96];
  std::snprintf(buf, sizeof buf, "; shape %.2g, %d of 3 edges present", 0.5 * (b - a).cross(c - a).norm() / (l * l),
                present);
  return format("triangle", l, s) + buf;
}

}  // namespace aniso::volume
