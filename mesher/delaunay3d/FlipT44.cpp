#include "mesher/delaunay3d/FlipT44.h"

#include <utility>

#include "mesher/delaunay3d/EdgeRing.h"
#include "mesher/delaunay3d/LocalRetriangulation.h"

namespace aniso::del3d {

bool canFlip44(const TetMesh& mesh, TetId t, int i, int j, int diagonal, Flip44Plan* plan) {
  if (!mesh.isAlive(t) || i < 0 || i > 3 || j < 0 || j > 3 || i == j) return false;
  if (diagonal != 0 && diagonal != 1) return false;
  std::array<TetId, 4> tets;
  std::array<VertexId, 4> c;
  if (closedEdgeRing(mesh, t, i, j, tets, c) != 4) return false;
  for (int m = 0; m < 4; ++m) {
    const TetId u = tets[m];
    if (mesh.isConstrained(u, mesh.localIndex(u, c[m])) || mesh.isConstrained(u, mesh.localIndex(u, c[(m + 1) % 4])))
      return false;
  }
  VertexId a = mesh.vertex(t, i), b = mesh.vertex(t, j);
  if (orientation(mesh, {a, b, c[0], c[1]}) < 0) std::swap(a, b);
  // With (a, b, c_m, c_{m+1}) positive, the tets around (c_s, c_{s+2}) are, in order:
  const VertexId c0 = c[diagonal], c1 = c[diagonal + 1], c2 = c[diagonal + 2], c3 = c[(diagonal + 3) % 4];
  Flip44Plan p;
  p.oldTets = tets;
  p.newTets[0] = {c0, c1, c2, b};
  p.newTets[1] = {c1, c0, c2, a};
  p.newTets[2] = {c2, c3, c0, b};
  p.newTets[3] = {c3, c2, c0, a};
  for (const auto& v : p.newTets)
    if (orientation(mesh, v) <= 0) return false;
  if (plan) *plan = p;
  return true;
}

std::array<TetId, 4> flip44(TetMesh& mesh, const Flip44Plan& plan) {
  std::array<TetId, 4> out;
  replaceTets(mesh, plan.oldTets, plan.newTets, out);
  return out;
}

}  // namespace aniso::del3d
