#include "mesher/volume/BoundaryCrossing.h"

namespace aniso::volume {

std::vector<del3d::VertexId> boundaryCrossing(const del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b,
                                              const EdgeGuard& isBoundaryEdge, Pipe& pipe) {
  segmentPipe(mesh, a, b, pipe);
  for (const FaceRef& f : pipe.faces) {
    if (!mesh.isConstrained(f.tet, f.face)) continue;
    std::vector<del3d::VertexId> v;
    for (int m = 0; m < 3; ++m) v.push_back(mesh.vertex(f.tet, del3d::kFaceVertex[f.face][m]));
    return v;
  }
  for (const EdgeRef& e : pipe.edges) {
    const del3d::VertexId x = mesh.vertex(e.tet, e.i), y = mesh.vertex(e.tet, e.j);
    if (isBoundaryEdge(x, y)) return {x, y};
  }
  return {};
}

}  // namespace aniso::volume
