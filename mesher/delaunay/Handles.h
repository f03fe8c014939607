#pragma once
// Typed handles of the 2D triangulation kernel (STYLE.md §2): a VertexId cannot be passed
// where a TriId is expected. Both wrap a 32-bit index into the flat arrays of
// Triangulation2d; an invalid (default-constructed) handle is the "none" sentinel: a
// boundary edge has no neighbour, a vertex outside every triangle has no triangle.
//
// Edges are addressed as (triangle, local index i): edge i is the one opposite vertex i,
// i.e. (v[i+1], v[i+2]) taken counter-clockwise.
#include <compare>
#include <cstdint>

namespace aniso::del2d {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

struct VertexId {
  std::uint32_t index = kNone;
  constexpr VertexId() = default;
  constexpr explicit VertexId(std::uint32_t i) : index(i) {}
  constexpr bool valid() const { return index != kNone; }
  constexpr auto operator<=>(const VertexId&) const = default;
};

struct TriId {
  std::uint32_t index = kNone;
  constexpr TriId() = default;
  constexpr explicit TriId(std::uint32_t i) : index(i) {}
  constexpr bool valid() const { return index != kNone; }
  constexpr auto operator<=>(const TriId&) const = default;
};

/// Local index i+1 and i+2 (mod 3) without division.
inline constexpr int kNext[3] = {1, 2, 0};
inline constexpr int kPrev[3] = {2, 0, 1};

}  // namespace aniso::del2d
