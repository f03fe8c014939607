#include "mesher/volume/Pipe.h"

#include <algorithm>
#include <array>
#include <utility>

#include "mesher/core/KeySet.h"
#include "mesher/delaunay3d/EdgeRing.h"
#include "mesher/volume/MeshQueries.h"
#include "mesher/volume/SegmentCrossing.h"

namespace aniso::volume {

using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

namespace {

constexpr int kTetEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/// Breadth-first exploration of the tets around a missing entity; `examine` looks at one
/// tet and returns the tets to explore next through `push`.
class Region {
 public:
  Region(const TetMesh& mesh, Pipe& pipe) : mesh_(mesh), pipe_(pipe) {
    pipe_.faces.clear();
    pipe_.edges.clear();
    pipe_.tets.clear();
    pipe_.degenerate = false;
  }
  ~Region() {
    auto& m = const_cast<TetMesh&>(mesh_);  // scratch mark, cleared here
    for (const TetId t : pipe_.tets) m.clearMark(t, TetMesh::kMarkB);
  }
  void push(TetId t) {
    if (!t.valid() || mesh_.hasMark(t, TetMesh::kMarkB)) return;
    const_cast<TetMesh&>(mesh_).setMark(t, TetMesh::kMarkB);
    pipe_.tets.push_back(t);
  }
  void pushStar(VertexId v) {
    vertexStar(mesh_, v, star_);
    for (const TetId t : star_) push(t);
  }
  void pushRing(TetId t, int i, int j) {
    del3d::edgeRing(mesh_, t, i, j, ring_);
    for (const TetId u : ring_.tets) push(u);
  }
  /// Each face once: keyed by the smaller of its two face codes (4·tet + face).
  bool newFace(TetId t, int f) {
    const std::uint32_t own = 4 * t.index + static_cast<std::uint32_t>(f), other = mesh_.adjacentCode(t, f);
    return faces_.insert(other == del3d::kNone ? own : std::min(own, other));
  }
  bool newEdge(TetId t, int i, int j) {
    std::uint64_t p = mesh_.vertex(t, i).index, q = mesh_.vertex(t, j).index;
    if (p > q) std::swap(p, q);
    return edges_.insert(p << 32 | q);
  }

 private:
  const TetMesh& mesh_;
  Pipe& pipe_;
  std::vector<TetId> star_;
  del3d::EdgeRing ring_;
  KeySet faces_, edges_;
};

/// Has vertex v: the entities of the stars of a missing edge's ends that contain an end
/// can neither be pierced nor crossed by it (SegmentCrossing.h: a shared endpoint is no
/// crossing), so they are not tested.
bool faceHas(const TetMesh& mesh, TetId t, int f, VertexId v) {
  const auto& fv = del3d::kFaceVertex[f];
  return mesh.vertex(t, fv[0]) == v || mesh.vertex(t, fv[1]) == v || mesh.vertex(t, fv[2]) == v;
}

}  // namespace

void segmentPipe(const TetMesh& mesh, VertexId a, VertexId b, Pipe& pipe) {
  Region region(mesh, pipe);
  region.pushStar(a);
  region.pushStar(b);
  const double* pa = mesh.coords(a);
  const double* pb = mesh.coords(b);
  for (std::size_t k = 0; k < pipe.tets.size(); ++k) {
    const TetId t = pipe.tets[k];
    for (int f = 0; f < 4; ++f) {
      if (faceHas(mesh, t, f, a) || faceHas(mesh, t, f, b) || !region.newFace(t, f)) continue;
      const auto& fv = del3d::kFaceVertex[f];
      const Cross c = segmentPiercesTriangle(pa, pb, mesh.coords(mesh.vertex(t, fv[0])),
                                             mesh.coords(mesh.vertex(t, fv[1])), mesh.coords(mesh.vertex(t, fv[2])));
      if (c == Cross::Degenerate) pipe.degenerate = true;
      if (c != Cross::Interior) continue;
      pipe.faces.push_back({t, f});
      region.push(mesh.neighbour(t, f));
    }
    for (const auto& e : kTetEdge) {
      const VertexId x = mesh.vertex(t, e[0]), y = mesh.vertex(t, e[1]);
      if (x == a || x == b || y == a || y == b || !region.newEdge(t, e[0], e[1])) continue;
      const Cross c = segmentsCross(pa, pb, mesh.coords(mesh.vertex(t, e[0])), mesh.coords(mesh.vertex(t, e[1])));
      if (c == Cross::Degenerate) pipe.degenerate = true;
      if (c != Cross::Interior) continue;
      pipe.edges.push_back({t, e[0], e[1]});
      region.pushRing(t, e[0], e[1]);
    }
  }
}

void trianglePipe(const TetMesh& mesh, VertexId a, VertexId b, VertexId c, Pipe& pipe) {
  Region region(mesh, pipe);
  region.pushStar(a);
  region.pushStar(b);
  region.pushStar(c);
  const double* pa = mesh.coords(a);
  const double* pb = mesh.coords(b);
  const double* pc = mesh.coords(c);
  for (std::size_t k = 0; k < pipe.tets.size(); ++k) {
    const TetId t = pipe.tets[k];
    for (const auto& e : kTetEdge) {
      if (!region.newEdge(t, e[0], e[1])) continue;
      const Cross x =
          segmentCrossesTriangle(mesh.coords(mesh.vertex(t, e[0])), mesh.coords(mesh.vertex(t, e[1])), pa, pb, pc);
      if (x == Cross::Degenerate) pipe.degenerate = true;
      if (x != Cross::Interior) continue;
      pipe.edges.push_back({t, e[0], e[1]});
      region.pushRing(t, e[0], e[1]);
    }
  }
}

}  // namespace aniso::volume
