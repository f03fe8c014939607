#include "mesher/delaunay3d/FlipT32.h"

#include <utility>

#include "mesher/delaunay3d/EdgeRing.h"
#include "mesher/delaunay3d/LocalRetriangulation.h"

namespace aniso::del3d {

bool canFlip32(const TetMesh& mesh, TetId t, int i, int j, Flip32Plan* plan) {
  if (!mesh.isAlive(t) || i < 0 || i > 3 || j < 0 || j > 3 || i == j) return false;
  std::array<TetId, 3> tets;
  std::array<VertexId, 3> c;
  if (closedEdgeRing(mesh, t, i, j, tets, c) != 3) return false;
  VertexId a = mesh.vertex(t, i), b = mesh.vertex(t, j);
  // Faces around the edge: (a, b, c[m]) between tets[m-1] and tets[m].
  for (int m = 0; m < 3; ++m) {
    const TetId u = tets[m];
    const int im = mesh.localIndex(u, c[m]), jm = mesh.localIndex(u, c[(m + 1) % 3]);
    // tets[m] holds a, b, c[m], c[m+1]: the faces around the edge are opposite c[m] and c[m+1].
    if (mesh.isConstrained(u, im) || mesh.isConstrained(u, jm)) return false;
  }
  // Orient the ring so that (a, b, c[m], c[m+1]) is positive.
  if (orientation(mesh, {a, b, c[0], c[1]}) < 0) std::swap(a, b);
  Flip32Plan p;
  p.oldTets = tets;
  p.newTets[0] = {c[0], c[1], c[2], b};
  p.newTets[1] = {c[1], c[0], c[2], a};
  for (const auto& v : p.newTets)
    if (orientation(mesh, v) <= 0) return false;
  if (plan) *plan = p;
  return true;
}

std::array<TetId, 2> flip32(TetMesh& mesh, const Flip32Plan& plan) {
  std::array<TetId, 2> out;
  replaceTets(mesh, plan.oldTets, plan.newTets, out);
  return out;
}

}  // namespace aniso::del3d
