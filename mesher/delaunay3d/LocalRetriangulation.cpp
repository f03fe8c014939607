#include "mesher/delaunay3d/LocalRetriangulation.h"

#include <algorithm>
#include <utility>

#include "mesher/core/Assert.h"
#include "mesher/core/Error.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::del3d {
namespace {

using Triple = std::array<std::uint32_t, 3>;

Triple sortedFace(const std::uint32_t* v, int i) {
  Triple f = {v[kFaceVertex[i][0]], v[kFaceVertex[i][1]], v[kFaceVertex[i][2]]};
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  if (f[1] > f[2]) std::swap(f[1], f[2]);
  if (f[0] > f[1]) std::swap(f[0], f[1]);
  return f;
}

struct OuterFace {
  Triple key;
  std::uint32_t code;  // neighbour across (kNone on the hull)
  bool constrained;
  bool used;
};

}  // namespace

double orientation(const TetMesh& mesh, const std::array<VertexId, 4>& v) {
  return predicates::orient3d(mesh.coords(v[0]), mesh.coords(v[1]), mesh.coords(v[2]), mesh.coords(v[3]));
}

void replaceTets(TetMesh& mesh, std::span<const TetId> oldTets,
                 std::span<const std::array<VertexId, 4>> newTets, std::span<TetId> out) {
  if (oldTets.size() > kMaxLocalTets || newTets.size() > kMaxLocalTets || out.size() != newTets.size())
    throw MeshingError("replaceTets: too many tetrahedra");
  if constexpr (kAssertsEnabled) {
    for (std::size_t a = 0; a < oldTets.size(); ++a) {
      ANISO_ASSERT(mesh.isAlive(oldTets[a]));
      for (std::size_t b = a + 1; b < oldTets.size(); ++b) ANISO_ASSERT(oldTets[a] != oldTets[b]);
    }
  }
  // Outer faces of the old set.
  std::array<OuterFace, 4 * kMaxLocalTets> outer;
  std::size_t nOuter = 0;
  for (const TetId t : oldTets) {
    for (int i = 0; i < 4; ++i) {
      const TetId n = mesh.neighbour(t, i);
      if (n.valid() && std::find(oldTets.begin(), oldTets.end(), n) != oldTets.end()) continue;
      outer[nOuter++] = {sortedFace(mesh.tetVertices(t), i), mesh.adjacentCode(t, i), mesh.isConstrained(t, i), false};
    }
  }
  // Match every face of the new set, first to an outer face, else to another new face.
  // match[4k+j] = index of the outer face, or 1000 + 4k'+j' for a new face.
  constexpr std::uint32_t kNewBase = 1000;
  std::array<std::uint32_t, 4 * kMaxLocalTets> match;
  std::array<Triple, 4 * kMaxLocalTets> keys;
  std::size_t nOuterUsed = 0;
  for (std::size_t k = 0; k < newTets.size(); ++k) {
    std::uint32_t raw[4];
    for (int m = 0; m < 4; ++m) raw[m] = newTets[k][m].index;
    for (int j = 0; j < 4; ++j) keys[4 * k + j] = sortedFace(raw, j);
  }
  for (std::size_t f = 0; f < 4 * newTets.size(); ++f) {
    match[f] = kNone;
    for (std::size_t o = 0; o < nOuter && match[f] == kNone; ++o) {
      if (!outer[o].used && outer[o].key == keys[f]) {
        outer[o].used = true;
        match[f] = static_cast<std::uint32_t>(o);
        ++nOuterUsed;
      }
    }
    for (std::size_t g = 0; g < 4 * newTets.size() && match[f] == kNone; ++g) {
      if (g != f && g / 4 != f / 4 && keys[g] == keys[f]) match[f] = kNewBase + static_cast<std::uint32_t>(g);
    }
    if (match[f] == kNone) throw MeshingError("replaceTets: new tetrahedra do not fill the old polyhedron");
  }
  if (nOuterUsed != nOuter) throw MeshingError("replaceTets: new tetrahedra do not cover the old boundary");

  mesh.setCertifiedDelaunay(false);
  for (const TetId t : oldTets) mesh.freeTet(t);
  for (std::size_t k = 0; k < newTets.size(); ++k)
    out[k] = mesh.createTet(newTets[k][0], newTets[k][1], newTets[k][2], newTets[k][3]);
  for (std::size_t f = 0; f < 4 * newTets.size(); ++f) {
    const TetId t = out[f / 4];
    const int j = static_cast<int>(f % 4);
    if (match[f] >= kNewBase) {
      const std::uint32_t g = match[f] - kNewBase;
      mesh.setAdjacentCode(t, j, faceCode(out[g / 4], static_cast<int>(g % 4)));
    } else {
      const OuterFace& o = outer[match[f]];
      mesh.setAdjacentCode(t, j, o.code);
      if (o.code != kNone) mesh.setAdjacentCode(codeTet(o.code), codeFace(o.code), faceCode(t, j));
      mesh.setConstrainedBit(t, j, o.constrained);
    }
    mesh.setVertexTet(newTets[f / 4][j], t);
  }
}

}  // namespace aniso::del3d
