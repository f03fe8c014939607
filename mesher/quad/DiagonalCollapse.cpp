#include "mesher/quad/DiagonalCollapse.h"

#include <algorithm>
#include <set>

#include "mesher/quad/QuadSmoothing.h"

namespace aniso::quad {
namespace {

/// Elements a vertex must keep after losing one: inner 4, boundary 2.
bool keepsEnough(const QuadMesh2d& mesh, const VertexElements& ve, int v) {
  const int n = static_cast<int>(ve.of(v).size());
  return mesh.boundary[v] ? n - 1 >= 2 : n - 1 >= 4;
}

std::set<int> neighbours(const QuadMesh2d& mesh, const VertexElements& ve, int v) {
  std::set<int> out;
  for (int e : ve.of(v)) {
    const int n = mesh.sides(e), i = mesh.cornerIndex(e, v);
    out.insert(mesh.corners[e][(i + 1) % n]);
    out.insert(mesh.corners[e][(i + n - 1) % n]);
  }
  return out;
}

/// Collapses quad q across its corners i and i + 2 when legal; returns whether it did.
bool collapse(QuadMesh2d& mesh, VertexMetrics& metrics, const VertexElements& ve, int q, int i, double minQuality) {
  const Corners c = mesh.corners[q];
  const int v0 = c[i], v1 = c[(i + 1) % 4], v2 = c[(i + 2) % 4], v3 = c[(i + 3) % 4];
  if (mesh.boundary[v0] || mesh.boundary[v2] || ve.of(v0).size() != 3 || ve.of(v2).size() != 3) return false;
  if (!keepsEnough(mesh, ve, v1) || !keepsEnough(mesh, ve, v3)) return false;
  std::set<int> common;
  const std::set<int> n0 = neighbours(mesh, ve, v0), n2 = neighbours(mesh, ve, v2);
  std::set_intersection(n0.begin(), n0.end(), n2.begin(), n2.end(), std::inserter(common, common.begin()));
  if (common != std::set<int>{v1, v3}) return false;
  std::vector<int> removed{q};
  std::vector<Corners> added;
  double before = 2;
  for (int v : {v0, v2})
    for (int e : ve.of(v)) {
      if (e == q) continue;
      if (mesh.cornerIndex(e, v0) != kNone && mesh.cornerIndex(e, v2) != kNone) return false;
      removed.push_back(e);
      Corners cn = mesh.corners[e];
      for (int& x : cn)
        if (x == v2) x = v0;
      added.push_back(cn);
      if (mesh.isQuad(e)) before = std::min(before, elementQuality(mesh, metrics, mesh.corners[e]));
    }
  const Vec2 old = mesh.uv[v0];
  mesh.uv[v0] = 0.5 * (mesh.uv[v0] + mesh.uv[v2]);
  metrics.invalidate(v0);
  const double floor = std::min(minQuality, before);
  bool legal = true;
  for (const Corners& cn : added) {
    const double quality = elementQuality(mesh, metrics, cn);
    legal = legal && (cn[3] == kNone ? quality > 0 : quality > 0 && quality >= floor);
  }
  if (!legal) {
    mesh.uv[v0] = old;
    metrics.invalidate(v0);
    return false;
  }
  mesh.replacePatch(removed, added);
  return true;
}

}  // namespace

int collapseDiagonals(QuadMesh2d& mesh, VertexMetrics& metrics, double minQuality) {
  VertexElements ve;
  ve.build(mesh);
  std::vector<std::uint8_t> touched(mesh.numVertices(), 0);
  int done = 0;
  const int n = mesh.numElements();
  for (int q = 0; q < n; ++q) {
    if (!mesh.isQuad(q)) continue;
    // Every vertex of the elements around the corners: untouched, their stars are as built.
    std::vector<int> around;
    bool fresh = true;
    for (int k = 0; k < 4; ++k)
      for (int e : ve.of(mesh.corners[q][k]))
        for (int j = 0; j < mesh.sides(e); ++j) {
          around.push_back(mesh.corners[e][j]);
          fresh = fresh && !touched[mesh.corners[e][j]];
        }
    if (!fresh) continue;
    for (int i = 0; i < 2; ++i) {
      if (!collapse(mesh, metrics, ve, q, i, minQuality)) continue;
      for (int v : around) touched[v] = 1;
      ++done;
      break;
    }
  }
  return done;
}

}  // namespace aniso::quad
