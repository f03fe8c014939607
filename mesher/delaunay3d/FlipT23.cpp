#include "mesher/delaunay3d/FlipT23.h"

#include "mesher/delaunay3d/LocalRetriangulation.h"

namespace aniso::del3d {

bool canFlip23(const TetMesh& mesh, TetId t, int face, Flip23Plan* plan) {
  if (!mesh.isAlive(t) || face < 0 || face > 3) return false;
  const std::uint32_t code = mesh.adjacentCode(t, face);
  if (code == kNone || mesh.isConstrained(t, face)) return false;
  const TetId u = codeTet(code);
  const VertexId e = mesh.vertex(u, codeFace(code));
  Flip23Plan p;
  p.oldTets = {t, u};
  // New tet k: t with its face vertex k replaced by e; it keeps d = t[face] and the
  // other two face vertices, so it is positive iff e is on the inner side of face k of t.
  int n = 0;
  for (int k = 0; k < 4; ++k) {
    if (k == face) continue;
    std::array<VertexId, 4> v = {mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2), mesh.vertex(t, 3)};
    v[k] = e;
    if (orientation(mesh, v) <= 0) return false;
    p.newTets[n++] = v;
  }
  if (plan) *plan = p;
  return true;
}

std::array<TetId, 3> flip23(TetMesh& mesh, const Flip23Plan& plan) {
  std::array<TetId, 3> out;
  replaceTets(mesh, plan.oldTets, plan.newTets, out);
  return out;
}

}  // namespace aniso::del3d
