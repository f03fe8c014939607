#include "mesher/delaunay3d/Locate.h"

#include <bit>

#include "mesher/core/Assert.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::del3d {
namespace {

inline std::uint32_t nextRandom(std::uint32_t& s) {
  s ^= s << 13;
  s ^= s >> 17;
  s ^= s << 5;
  return s;
}

// orient3d of t with its vertex i replaced by p: > 0 iff p is on the inner side of face i.
inline double faceOrient(const TetMesh& mesh, const std::uint32_t* tv, int i, const double* p) {
  const double* c[4] = {mesh.coords(VertexId(tv[0])), mesh.coords(VertexId(tv[1])),
                        mesh.coords(VertexId(tv[2])), mesh.coords(VertexId(tv[3]))};
  c[i] = p;
  return predicates::orient3d(c[0], c[1], c[2], c[3]);
}

void classify(const TetMesh& mesh, TetId t, unsigned zeros, LocateResult& r) {
  r.tet = t;
  r.zeroFaces = zeros;
  switch (std::popcount(zeros)) {
    case 0: r.status = LocateStatus::Inside; break;
    case 1: r.status = LocateStatus::OnFace; break;
    case 2: r.status = LocateStatus::OnEdge; break;
    default: {
      r.status = LocateStatus::OnVertex;
      for (int m = 0; m < 4; ++m)
        if (!((zeros >> m) & 1u)) r.vertex = mesh.vertex(t, m);
    }
  }
}

// Exact scan of every tetrahedron: the fallback when the walk exceeds its budget.
void scan(const TetMesh& mesh, const double p[3], LocateResult& r) {
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k) {
    const TetId t(k);
    if (!mesh.isAlive(t)) continue;
    const std::uint32_t* tv = mesh.tetVertices(t);
    unsigned zeros = 0;
    bool inside = true;
    for (int i = 0; i < 4 && inside; ++i) {
      const double o = faceOrient(mesh, tv, i, p);
      if (o < 0) inside = false;
      else if (o == 0) zeros |= 1u << i;
    }
    if (inside) {
      classify(mesh, t, zeros, r);
      return;
    }
  }
  r.status = LocateStatus::Outside;
  r.face = -1;
}

}  // namespace

LocateResult locate(const TetMesh& mesh, const double p[3], TetId start, std::uint32_t& rng) {
  ANISO_ASSERT(mesh.isAlive(start));
  LocateResult r;
  if (rng == 0) rng = 0x9E3779B9u;
  const std::uint64_t budget = 4 * std::uint64_t{mesh.tetSlots()} + 64;
  TetId t = start;
  std::uint32_t prev = kNone;
  for (;;) {
    if (++r.steps > budget) {
      scan(mesh, p, r);
      return r;
    }
    const std::uint32_t* tv = mesh.tetVertices(t);
    const std::uint32_t first = nextRandom(rng) >> 30;
    int exitFace = -1, hullFace = -1;
    unsigned zeros = 0;
    for (std::uint32_t k = 0; k < 4; ++k) {
      const int i = static_cast<int>((first + k) & 3u);
      const std::uint32_t code = mesh.adjacentCode(t, i);
      if (code != kNone && (code >> 2) == prev) continue;  // p is strictly on our side
      const double o = faceOrient(mesh, tv, i, p);
      if (o < 0) {
        if (code == kNone) {
          hullFace = i;
          continue;
        }
        exitFace = i;
        break;
      }
      if (o == 0) zeros |= 1u << i;
    }
    if (exitFace >= 0) {
      prev = t.index;
      t = mesh.neighbour(t, exitFace);
      continue;
    }
    if (hullFace >= 0) {
      r.status = LocateStatus::Outside;
      r.tet = t;
      r.face = hullFace;
      return r;
    }
    classify(mesh, t, zeros, r);
    return r;
  }
}

}  // namespace aniso::del3d
