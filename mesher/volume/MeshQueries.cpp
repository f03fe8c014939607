#include "mesher/volume/MeshQueries.h"

namespace aniso::volume {

using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

void vertexStar(const TetMesh& mesh, VertexId v, std::vector<TetId>& out) {
  out.clear();
  const TetId first = mesh.vertexTet(v);
  if (!first.valid() || !mesh.isAlive(first)) return;
  auto& m = const_cast<TetMesh&>(mesh);  // scratch mark only, cleared before returning
  m.setMark(first, TetMesh::kMarkB);
  out.push_back(first);
  for (std::size_t k = 0; k < out.size(); ++k) {
    const TetId t = out[k];
    for (int i = 0; i < 4; ++i) {
      if (mesh.vertex(t, i) == v) continue;  // the face opposite v does not contain it
      const TetId n = mesh.neighbour(t, i);
      if (!n.valid() || mesh.hasMark(n, TetMesh::kMarkB)) continue;
      m.setMark(n, TetMesh::kMarkB);
      out.push_back(n);
    }
  }
  for (const TetId t : out) m.clearMark(t, TetMesh::kMarkB);
}

EdgeHandle findEdgeInStar(const TetMesh& mesh, VertexId a, VertexId b, const std::vector<TetId>& star) {
  for (const TetId t : star) {
    const int j = mesh.localIndex(t, b);
    if (j >= 0) return {t, mesh.localIndex(t, a), j};
  }
  return {};
}

EdgeHandle findEdge(const TetMesh& mesh, VertexId a, VertexId b, std::vector<TetId>& star) {
  vertexStar(mesh, a, star);
  return findEdgeInStar(mesh, a, b, star);
}

FaceHandle findFaceInStar(const TetMesh& mesh, VertexId a, VertexId b, VertexId c, const std::vector<TetId>& star) {
  for (const TetId t : star) {
    if (mesh.localIndex(t, b) < 0 || mesh.localIndex(t, c) < 0) continue;
    for (int i = 0; i < 4; ++i) {
      const VertexId w = mesh.vertex(t, i);
      if (w != a && w != b && w != c) return {t, i};
    }
  }
  return {};
}

FaceHandle findFace(const TetMesh& mesh, VertexId a, VertexId b, VertexId c, std::vector<TetId>& star) {
  vertexStar(mesh, a, star);
  return findFaceInStar(mesh, a, b, c, star);
}

}  // namespace aniso::volume
