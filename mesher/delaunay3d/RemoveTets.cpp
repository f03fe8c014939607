#include "mesher/delaunay3d/RemoveTets.h"

namespace aniso::del3d {

std::vector<TetId> tetsTouching(const TetMesh& mesh, std::span<const VertexId> vertices) {
  std::vector<char> flag(mesh.numVertices(), 0);
  for (const VertexId v : vertices)
    if (v.index < flag.size()) flag[v.index] = 1;
  std::vector<TetId> out;
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k) {
    const TetId t(k);
    if (!mesh.isAlive(t)) continue;
    const std::uint32_t* tv = mesh.tetVertices(t);
    if (flag[tv[0]] || flag[tv[1]] || flag[tv[2]] || flag[tv[3]]) out.push_back(t);
  }
  return out;
}

void removeTets(TetMesh& mesh, std::span<const TetId> tets) {
  constexpr std::uint8_t kGone = TetMesh::kMarkA;
  std::vector<TetId> gone;
  gone.reserve(tets.size());
  for (const TetId t : tets) {
    if (!mesh.isAlive(t) || mesh.hasMark(t, kGone)) continue;
    mesh.setMark(t, kGone);
    gone.push_back(t);
  }
  // Cut the links to survivors and hand vertex references over to them.
  for (const TetId t : gone) {
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t code = mesh.adjacentCode(t, i);
      if (code == kNone) continue;
      const TetId n = codeTet(code);
      if (mesh.hasMark(n, kGone)) continue;
      mesh.setAdjacentCode(n, codeFace(code), kNone);
      const std::uint32_t* nv = mesh.tetVertices(n);
      for (int m = 0; m < 4; ++m) {
        const TetId vt = mesh.vertexTet(VertexId(nv[m]));
        if (!vt.valid() || mesh.hasMark(vt, kGone)) mesh.setVertexTet(VertexId(nv[m]), n);
      }
    }
  }
  // Vertices whose reference still points at a removed tet: search the survivors (only
  // needed when a vertex star is not face-connected), else clear.
  std::vector<VertexId> orphans;
  for (const TetId t : gone) {
    for (int m = 0; m < 4; ++m) {
      const VertexId v = mesh.vertex(t, m);
      const TetId vt = mesh.vertexTet(v);
      if (vt.valid() && mesh.hasMark(vt, kGone)) {
        mesh.setVertexTet(v, TetId());
        orphans.push_back(v);
      }
    }
  }
  for (const TetId t : gone) mesh.freeTet(t);
  if (orphans.empty()) return;
  std::vector<char> wanted(mesh.numVertices(), 0);
  for (const VertexId v : orphans) wanted[v.index] = 1;
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k) {
    const TetId t(k);
    if (!mesh.isAlive(t)) continue;
    for (int m = 0; m < 4; ++m) {
      const VertexId v = mesh.vertex(t, m);
      if (wanted[v.index]) {
        mesh.setVertexTet(v, t);
        wanted[v.index] = 0;
      }
    }
  }
}

}  // namespace aniso::del3d
