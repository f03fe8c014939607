#include "mesher/quad/FrontSeam.h"

#include <algorithm>
#include <set>

#include "mesher/quad/SideEdge.h"

namespace aniso::quad {
namespace {

std::set<int> neighbours(const QuadMesh2d& mesh, int v, int hint) {
  std::vector<int> around;
  bool closed = false;
  mesh.star(v, hint, around, closed);
  std::set<int> out;
  for (int g : around) {
    const int n = mesh.sides(g), i = mesh.cornerIndex(g, v);
    out.insert(mesh.corners[g][(i + 1) % n]);
    out.insert(mesh.corners[g][(i + n - 1) % n]);
  }
  return out;
}

}  // namespace

bool seamCorner(const QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, bool left, double seamAngle,
                SeamCorner& out) {
  const int a = mesh.corners[e][left ? k : (k + 1) % 3];
  const RegionFan fan = regionFan(mesh, metrics, a, e, left);
  if (fan.closed || fan.triangles.size() != 1 || !(fan.angle.back() < seamAngle)) return false;
  const int i = mesh.cornerIndex(e, a);
  out = {a, mesh.corners[e][(i + 1) % 3], mesh.corners[e][(i + 2) % 3], i};
  return true;
}

SeamResult closeSeam(QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, bool left, const SeamOptions& o) {
  SeamResult r;
  SeamCorner sc;
  if (!seamCorner(mesh, metrics, e, k, left, o.seamAngle, sc)) return r;
  // b, c: the far ends of the two front edges.
  const int a = sc.a, b = sc.b, c = sc.c, i = sc.i;
  if (mesh.boundary[b] && mesh.boundary[c]) return r;
  const int g = mesh.adj[e][(i + 1) % 3];
  if (g == kNone || !mesh.isTriangle(g)) return r;
  const int x = mesh.corners[g][(mesh.edgeIndex(g, c, b) + 2) % 3];
  std::set<int> common;
  const std::set<int> nb = neighbours(mesh, b, e), nc = neighbours(mesh, c, e);
  std::set_intersection(nb.begin(), nb.end(), nc.begin(), nc.end(), std::inserter(common, common.begin()));
  if (common != std::set<int>{a, x}) return r;
  // Keep the boundary one (or b), move it to the merged position.
  const int keep = mesh.boundary[c] ? c : b, gone = keep == b ? c : b;
  std::vector<int> removed, starKeep, starGone;
  bool closed = false;
  mesh.star(keep, e, starKeep, closed);
  mesh.star(gone, e, starGone, closed);
  removed = starKeep;
  for (int f : starGone)
    if (std::find(removed.begin(), removed.end(), f) == removed.end()) removed.push_back(f);
  std::vector<Corners> added;
  std::vector<double> before;
  for (int f : removed) {
    if (f == e || f == g) continue;
    Corners cn = mesh.corners[f];
    for (int& v : cn)
      if (v == gone) v = keep;
    added.push_back(cn);
    before.push_back(mesh.isQuad(f) ? elementQuality(mesh, metrics, mesh.corners[f]) : 0.0);
  }
  const Vec2 old = mesh.uv[keep];
  if (!mesh.boundary[keep]) mesh.uv[keep] = 0.5 * (mesh.uv[b] + mesh.uv[c]);
  metrics.invalidate(keep);
  metrics.refreshPoint(keep);
  bool legal = true;
  for (std::size_t j = 0; j < added.size() && legal; ++j) {
    const double q = elementQuality(mesh, metrics, added[j]);
    legal = added[j][3] == kNone ? q > 0 : q >= std::min(o.minQuality, before[j]) && q > 0;
  }
  if (!legal) {
    mesh.uv[keep] = old;
    metrics.invalidate(keep);
    metrics.refreshPoint(keep);
    return r;
  }
  const std::vector<int> ids = mesh.replacePatch(removed, added);
  r.done = true;
  r.vertex = keep;
  r.element = ids.empty() ? kNone : ids.front();
  return r;
}

}  // namespace aniso::quad
