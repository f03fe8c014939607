#include "mesher/volume/EdgeRemoval.h"

#include <utility>

#include "mesher/delaunay3d/EdgeRing.h"

namespace aniso::volume {

using del3d::TetId;
using del3d::VertexId;

int removalRingSize(const del3d::TetMesh& mesh, TetId t, int i, int j) {
  std::array<TetId, kMaxRemovalRing> tets;
  std::array<VertexId, kMaxRemovalRing> apex;
  return del3d::closedEdgeRing(mesh, t, i, j, tets, apex);
}

bool canRemoveEdge(const del3d::TetMesh& mesh, TetId t, int i, int j, int fan, LocalPlan* plan) {
  if (!mesh.isAlive(t) || i < 0 || i > 3 || j < 0 || j > 3 || i == j) return false;
  std::array<TetId, kMaxRemovalRing> tets;
  std::array<VertexId, kMaxRemovalRing> c;
  const int n = del3d::closedEdgeRing(mesh, t, i, j, tets, c);
  if (n < 3 || fan < 0 || fan >= n) return false;
  for (int m = 0; m < n; ++m)  // a ring through the same vertex twice is no polygon
    for (int k = m + 1; k < n; ++k)
      if (c[m] == c[k]) return false;
  for (int m = 0; m < n; ++m) {
    const TetId u = tets[m];
    if (mesh.isConstrained(u, mesh.localIndex(u, c[m])) || mesh.isConstrained(u, mesh.localIndex(u, c[(m + 1) % n])))
      return false;
  }
  VertexId a = mesh.vertex(t, i), b = mesh.vertex(t, j);
  if (del3d::orientation(mesh, {a, b, c[0], c[1]}) < 0) std::swap(a, b);
  LocalPlan p;
  p.oldTets.assign(tets.begin(), tets.begin() + n);
  for (const TetId u : p.oldTets)
    p.oldQuads.push_back({mesh.vertex(u, 0), mesh.vertex(u, 1), mesh.vertex(u, 2), mesh.vertex(u, 3)});
  const VertexId s = c[fan];
  for (int k = 1; k + 1 < n; ++k) {
    const VertexId x = c[(fan + k) % n], y = c[(fan + k + 1) % n];
    p.newTets.push_back({s, x, y, b});
    p.newTets.push_back({x, s, y, a});
  }
  for (const auto& v : p.newTets)
    if (del3d::orientation(mesh, v) <= 0) return false;
  if (plan) *plan = std::move(p);
  return true;
}

}  // namespace aniso::volume
