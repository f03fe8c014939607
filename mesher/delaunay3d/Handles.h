#pragma once
// Typed handles of the 3D Delaunay kernel (STYLE.md §2): a VertexId cannot be passed where
// a TetId is expected. Both wrap a 32-bit index into the flat arrays of TetMesh; kNone is
// the "no element" sentinel (a hull face has no neighbour, a removed vertex no tet).
//
// Faces are addressed as (tet, local index i), face i being the one opposite vertex i.
// Neighbour slots store the code 4·tet + j of the SAME face seen from the neighbour, so the
// way back is recovered without a search (geogram delaunay_3d, "adjacent facet" encoding).
#include <compare>
#include <cstdint>

namespace aniso::del3d {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

struct VertexId {
  std::uint32_t index = kNone;
  constexpr VertexId() = default;
  constexpr explicit VertexId(std::uint32_t i) : index(i) {}
  constexpr bool valid() const { return index != kNone; }
  constexpr auto operator<=>(const VertexId&) const = default;
};

struct TetId {
  std::uint32_t index = kNone;
  constexpr TetId() = default;
  constexpr explicit TetId(std::uint32_t i) : index(i) {}
  constexpr bool valid() const { return index != kNone; }
  constexpr auto operator<=>(const TetId&) const = default;
};

/// Face code 4·tet + i (i = local face index, opposite local vertex i); kNone = no face.
constexpr std::uint32_t faceCode(TetId t, int i) { return 4u * t.index + static_cast<std::uint32_t>(i); }
constexpr TetId codeTet(std::uint32_t code) { return code == kNone ? TetId() : TetId(code >> 2); }
constexpr int codeFace(std::uint32_t code) { return static_cast<int>(code & 3u); }

/// Local vertex indices of face i of a tetrahedron (v0,v1,v2,v3), ordered so that
/// (f[0], f[1], f[2], v_i) is an even permutation of (0,1,2,3): for a positive tet,
/// orient3d(v_f0, v_f1, v_f2, v_i) > 0 (the face is clockwise seen from v_i).
inline constexpr int kFaceVertex[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

}  // namespace aniso::del3d
