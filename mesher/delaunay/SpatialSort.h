#pragma once
// Insertion orders for incremental triangulation. Thesis sec. 4.4 inserts boundary nodes
// "in randomized order … Randomization improves the efficiency … by increasing the quality
// of the intermediate structure"; a spatially coherent order additionally keeps the walks
// of point location short and the memory accesses local.
//
//   hilbertOrder  — the points sorted along a Hilbert curve over their bounding box
//                   (coordinates quantised to 2^16 cells per axis, radix-sorted);
//   brioOrder     — Biased Randomized Insertion Order (Amenta, Choi & Rote 2003): a random
//                   permutation split into rounds of doubling size (the last round holds
//                   about half of the points), each round sorted along the Hilbert curve.
//                   Random enough for the expected-case bounds, local enough to be fast.
// Both return a permutation of [0, points.size()); non-finite points are put last.
// Deterministic for a given seed.
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso::del2d {

/// Hilbert index of the cell (x, y) of a 2^bits × 2^bits grid (bits ≤ 31).
std::uint64_t hilbertIndex(std::uint32_t x, std::uint32_t y, int bits);

std::vector<std::uint32_t> hilbertOrder(std::span<const Vec2> points);

/// minRound: rounds are not split below this size.
std::vector<std::uint32_t> brioOrder(std::span<const Vec2> points, std::uint64_t seed = 0x5EEDu,
                                     std::uint32_t minRound = 64);

}  // namespace aniso::del2d
