#pragma once
// Steps 2-3 of INTERIOR-CAVITY recovery (CavityRecovery.h) on a patch I of missing
// boundary triangles:
//  collectCavity — the cavity C: every tet crossed by a triangle of I (around each mesh
//    edge crossing it) or by a missing edge of I (beside each face it pierces, around each
//    edge it crosses) (Pipe.h), the tets on both sides of the present triangles of I and
//    around the present edges inside I;
//  splitSides — C's boundary faces (oriented into C) split across the rim edges of I into
//    the outer (material's outside) and the inner side, with the tet across each face;
//  growSide — a side without a star takes in the tets beyond the faces that a point near
//    its kernel does not see (not across constrained faces, not touching the rim).
#include <cstdint>
#include <map>
#include <unordered_set>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"
#include "mesher/volume/CavityStar.h"

namespace aniso::volume {

/// Status codes of the cavity steps (0 is success).
inline constexpr int kCavityFailed = -1;
inline constexpr int kCavitySidesMixed = -2;  ///< the rim of I does not separate the sides

std::uint64_t cavityEdgeKey(std::uint32_t a, std::uint32_t b);

/// The edges of I by key: how many triangles of I use each (1 = rim edge), and one
/// triangle using it.
struct PatchEdges {
  std::map<std::uint64_t, int> uses;
  std::map<std::uint64_t, int> triangle;
  bool isRim(std::uint64_t key) const {
    const auto it = uses.find(key);
    return it != uses.end() && it->second == 1;
  }
};
PatchEdges patchEdges(const std::vector<CavityFace>& tris, const std::vector<int>& patch);

struct Cavity {
  std::vector<del3d::TetId> tets;
  std::unordered_set<std::uint32_t> in;
  void add(del3d::TetId t) {
    if (t.valid() && in.insert(t.index).second) tets.push_back(t);
  }
};

/// Fills `c`; kCavityFailed when a pipe is degenerate or C is empty.
int collectCavity(const del3d::TetMesh& m, const std::vector<CavityFace>& tris, const std::vector<int>& patch,
                  const PatchEdges& edges, Cavity& c);

struct CavitySides {
  int status = 0;  ///< 0, kCavityFailed or kCavitySidesMixed
  std::vector<CavityFace> inner, outer;
  std::vector<del3d::TetId> innerNext, outerNext;  ///< tet across each face (invalid: constrained)
};

CavitySides splitSides(const del3d::TetMesh& m, const Cavity& c, const PatchEdges& edges,
                       const std::vector<CavityFace>& tris);

/// Grows `c` on one side (its faces and the tets across them) towards a star around a
/// point near its kernel, seeded at `start` (margin `margin`).
void growSide(const del3d::TetMesh& m, const std::vector<CavityFace>& faces, const std::vector<del3d::TetId>& next,
              const PatchEdges& edges, const Vec3& start, double margin, Cavity& c);

}  // namespace aniso::volume
