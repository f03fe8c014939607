#include "mesher/quad/SideEdge.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "mesher/quad/TriangleFlip.h"

namespace aniso::quad {
namespace {

/// Unsigned metric angle between the rays v→x and v→y.
double rayAngle(const QuadMesh2d& mesh, const Mat2& s, int v, int x, int y) {
  const Vec2 p = s * (mesh.uv[x] - mesh.uv[v]), q = s * (mesh.uv[y] - mesh.uv[v]);
  return std::abs(std::atan2(p.x() * q.y() - p.y() * q.x(), p.dot(q)));
}

/// Swaps the edge (x, y) of triangle f = (v, x, y) opposite v (TriangleFlip.h). Returns the
/// new corner w, or kNone.
int swapOpposite(QuadMesh2d& mesh, int f, int v) { return flipTriangleEdge(mesh, f, (mesh.cornerIndex(f, v) + 1) % 3); }

/// Splits the inner edge (v, x) of the region at its midpoint: its two triangles become
/// four (always strictly convex: halves of valid triangles). Returns the midpoint, or kNone.
int splitEdge(QuadMesh2d& mesh, VertexMetrics& metrics, int v, int x, int hint) {
  int f = kNone;
  std::vector<int> around;
  bool closed = false;
  mesh.star(v, hint, around, closed);
  for (int g : around)
    if (mesh.isTriangle(g) && mesh.edgeIndex(g, v, x) != kNone) f = g;
  if (f == kNone) return kNone;
  const int k = mesh.edgeIndex(f, v, x);
  const int g = mesh.adj[f][k];
  if (g == kNone || !mesh.isTriangle(g)) return kNone;
  const int y = mesh.corners[f][(k + 2) % 3];
  const int z = mesh.corners[g][(mesh.edgeIndex(g, x, v) + 2) % 3];
  const int m = mesh.addVertex(0.5 * (mesh.uv[v] + mesh.uv[x]));
  metrics.invalidate(m);
  const std::array<Corners, 4> added{Corners{v, m, y, kNone}, Corners{m, x, y, kNone}, Corners{x, m, z, kNone},
                                     Corners{m, v, z, kNone}};
  for (const Corners& c : added)
    if (!convexCCW(mesh, c)) {
      mesh.removeLastVertex();
      return kNone;
    }
  const std::array<int, 2> removed{f, g};
  mesh.replacePatch(removed, added);
  return m;
}

}  // namespace

RegionFan regionFan(const QuadMesh2d& mesh, VertexMetrics& metrics, int v, int e, bool ccw) {
  RegionFan fan;
  const Mat2& s = metrics.at(v);
  int f = e;
  {
    const int i = mesh.cornerIndex(f, v);
    fan.rays.push_back(mesh.corners[f][ccw ? (i + 1) % 3 : (i + 2) % 3]);
    fan.angle.push_back(0);
  }
  while (static_cast<int>(fan.triangles.size()) < 256) {
    const int i = mesh.cornerIndex(f, v);
    fan.triangles.push_back(f);
    const int far = mesh.corners[f][ccw ? (i + 2) % 3 : (i + 1) % 3];
    fan.angle.push_back(fan.angle.back() + rayAngle(mesh, s, v, fan.rays.back(), far));
    fan.rays.push_back(far);
    const int g = mesh.adj[f][ccw ? (i + 2) % 3 : i];
    if (g == e) {
      fan.closed = true;
      break;
    }
    if (g == kNone || !mesh.isTriangle(g)) break;
    f = g;
  }
  return fan;
}

int triangleWithEdge(const QuadMesh2d& mesh, int a, int b, int hint) {
  if (hint == kNone || !mesh.alive(hint) || mesh.cornerIndex(hint, a) == kNone) return kNone;
  std::vector<int> around;
  bool closed = false;
  mesh.star(a, hint, around, closed);
  for (int f : around)
    if (mesh.isTriangle(f) && mesh.edgeIndex(f, a, b) != kNone) return f;
  return kNone;
}

namespace {

/// The best candidate split when longer than maxLengthRatio × `base` (metric).
void splitLong(QuadMesh2d& mesh, VertexMetrics& metrics, int v, int hint, double base, SideEdge& side,
               const SideOptions& o) {
  const int x = side.vertices.front();
  if (!(base > 0) || metrics.length(v, x) <= o.maxLengthRatio * base) return;
  const int m = splitEdge(mesh, metrics, v, x, hint);
  if (m == kNone) return;
  side.vertices.front() = m;
  side.split = true;
}

}  // namespace

SideEdge selectSideEdge(QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, bool left, const SideOptions& o) {
  SideEdge side;
  const int v = mesh.corners[e][left ? k : (k + 1) % 3];
  const double base = metrics.length(mesh.corners[e][k], mesh.corners[e][(k + 1) % 3]);
  const RegionFan fan = regionFan(mesh, metrics, v, e, left);
  if (fan.closed) return side;
  const double alpha = fan.angle.back();
  if (alpha < o.sideAngle) {
    side.vertices.push_back(fan.rays.back());
    side.front = true;
    return side;
  }
  const double half = 0.5 * alpha;
  std::vector<std::pair<double, int>> near;
  for (std::size_t j = 1; j + 1 < fan.rays.size(); ++j)
    if (std::abs(fan.angle[j] - half) < o.bisectorTolerance) near.push_back({std::abs(fan.angle[j] - half), fan.rays[j]});
  std::sort(near.begin(), near.end());
  for (const auto& [off, x] : near) side.vertices.push_back(x);
  if (!near.empty()) {
    splitLong(mesh, metrics, v, e, base, side, o);
    return side;
  }
  // The triangle the bisector runs through, its edge opposite v swapped.
  for (std::size_t j = 0; j < fan.triangles.size(); ++j) {
    if (!(fan.angle[j] < half && half < fan.angle[j + 1])) continue;
    const int f = fan.triangles[j];
    // Left: f = (v, ray j, ray j+1); right: f = (v, ray j+1, ray j). swapOpposite works on f's own order.
    const int w = swapOpposite(mesh, f, v);
    if (w == kNone) return side;
    const Mat2& s = metrics.at(v);
    const double a = fan.angle[j] + rayAngle(mesh, s, v, fan.rays[j], w);
    if (std::abs(a - half) < o.bisectorTolerance) {
      side.vertices.push_back(w);
      side.swapped = true;
      splitLong(mesh, metrics, v, mesh.numElements() - 1, base, side, o);
    }
    return side;
  }
  return side;
}

}  // namespace aniso::quad
