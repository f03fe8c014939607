#pragma once
// Spatial sorting of the insertion order: Hilbert curve order and BRIO (Amenta, Choi &
// Rote 2003, "biased randomized insertion order") as in CGAL's spatial_sort. Inserting in
// this order keeps the location walk from the last created tet to a few steps while the
// randomization keeps the expected cavity sizes of a random order (thesis sec. 5.3:
// "boundary nodes are inserted one by one, in randomized order").
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso::del3d {

/// Position of the cell (x, y, z) along the 3D Hilbert curve of 2^bits cells per axis
/// (bits in 1..21, coordinates < 2^bits). Consecutive positions are face-adjacent cells.
std::uint64_t hilbertIndex(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits);
/// The same by Skilling's bit loop (the definition; tests compare hilbertIndex with it).
std::uint64_t hilbertIndexReference(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits);

/// Indices of `points` sorted along a Hilbert curve over their bounding box (about
/// 16·n^(1/3) cells per axis, at most 2^21; points in one cell are ordered by index).
/// Non-finite points are put last.
std::vector<std::uint32_t> hilbertOrder(std::span<const Vec3> points);

/// BRIO: a random permutation (deterministic for a given seed) split into rounds, the last
/// holding a fraction (1 − ratio) of the points, the one before (1 − ratio) of the rest,
/// and so on down to `minRound` points; each round is sorted along the Hilbert curve.
/// ratio in (0, 1).
std::vector<std::uint32_t> brioOrder(std::span<const Vec3> points, std::uint64_t seed = 0x5EEDu,
                                     double ratio = 0.25, std::size_t minRound = 64);

}  // namespace aniso::del3d
