#include "mesher/delaunay/SpatialSort.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <utility>

namespace aniso::del2d {
namespace {

// 2^16 cells per axis: a 32-bit key, fine enough for any point count the kernel handles
// (ties inside a cell keep their relative order, which is harmless).
constexpr int kBits = 16;

/// Stable LSD radix sort of (key, value) pairs by the 32-bit key, 8 bits per pass.
void radixSort(std::vector<std::pair<std::uint32_t, std::uint32_t>>& a) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> tmp(a.size());
  for (int shift = 0; shift < 32; shift += 8) {
    std::size_t count[257] = {};
    for (const auto& e : a) ++count[((e.first >> shift) & 0xFFu) + 1];
    if (count[1] == a.size() || a.empty()) continue;  // all keys share this byte
    for (int b = 0; b < 256; ++b) count[b + 1] += count[b];
    for (const auto& e : a) tmp[count[(e.first >> shift) & 0xFFu]++] = e;
    a.swap(tmp);
  }
}

/// Hilbert keys of all points over `box`, computed in point order (sequential access);
/// non-finite points get the largest key.
std::vector<std::uint32_t> hilbertKeys(std::span<const Vec2> pts, const Box2& box) {
  const double cells = std::ldexp(1.0, kBits);
  const Vec2 size = box.size();
  const double sx = size.x() > 0 ? cells / size.x() : 0.0, sy = size.y() > 0 ? cells / size.y() : 0.0;
  auto quantise = [&](double v, double lo, double s) {
    const double q = std::floor((v - lo) * s);
    return static_cast<std::uint32_t>(std::clamp(q, 0.0, cells - 1));
  };
  std::vector<std::uint32_t> keys(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Vec2& p = pts[k];
    keys[k] = p.allFinite() ? static_cast<std::uint32_t>(hilbertIndex(quantise(p.x(), box.lo.x(), sx),
                                                                       quantise(p.y(), box.lo.y(), sy), kBits))
                            : 0xFFFFFFFFu;
  }
  return keys;
}

/// Sorts idx[first, last) by key (stable).
void sortRange(const std::vector<std::uint32_t>& keys, std::vector<std::uint32_t>& idx, std::size_t first,
               std::size_t last, std::vector<std::pair<std::uint32_t, std::uint32_t>>& keyed) {
  keyed.clear();
  for (std::size_t k = first; k < last; ++k) keyed.emplace_back(keys[idx[k]], idx[k]);
  radixSort(keyed);
  for (std::size_t k = first; k < last; ++k) idx[k] = keyed[k - first].second;
}

Box2 finiteBox(std::span<const Vec2> pts) {
  Box2 box;
  for (const Vec2& p : pts)
    if (p.allFinite()) box.add(p);
  return box;
}

}  // namespace

std::uint64_t hilbertIndex(std::uint32_t x, std::uint32_t y, int bits) {
  // Quadrant by quadrant from the most significant bit; the sub-square is reflected or
  // transposed so that the curve in it starts where the previous quadrant ended
  // (branch-free: n − v = n ^ v for the all-ones mask n).
  std::uint64_t d = 0;
  const std::uint32_t n = bits >= 32 ? 0xFFFFFFFFu : ((1u << bits) - 1u);
  for (std::uint32_t s = 1u << (bits - 1); s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1u : 0u, ry = (y & s) ? 1u : 0u;
    d += static_cast<std::uint64_t>(s) * s * ((3u * rx) ^ ry);
    const std::uint32_t flip = 0u - (rx & (ry ^ 1u));  // reflect when rx = 1, ry = 0
    x ^= flip & n;
    y ^= flip & n;
    const std::uint32_t t = (x ^ y) & (0u - (ry ^ 1u));  // transpose when ry = 0
    x ^= t;
    y ^= t;
  }
  return d;
}

std::vector<std::uint32_t> hilbertOrder(std::span<const Vec2> points) {
  std::vector<std::uint32_t> idx(points.size());
  std::iota(idx.begin(), idx.end(), 0u);
  const std::vector<std::uint32_t> keys = hilbertKeys(points, finiteBox(points));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed;
  keyed.reserve(points.size());
  sortRange(keys, idx, 0, idx.size(), keyed);
  // Non-finite points share the largest key with finite ones in the last cell: move them last.
  if (std::any_of(keys.begin(), keys.end(), [](std::uint32_t k) { return k == 0xFFFFFFFFu; }))
    std::stable_partition(idx.begin(), idx.end(), [&](std::uint32_t i) { return points[i].allFinite(); });
  return idx;
}

std::vector<std::uint32_t> brioOrder(std::span<const Vec2> points, std::uint64_t seed, std::uint32_t minRound) {
  std::vector<std::uint32_t> idx(points.size());
  std::iota(idx.begin(), idx.end(), 0u);
  std::mt19937_64 rng(seed);
  std::shuffle(idx.begin(), idx.end(), rng);
  // Non-finite points go last (they are refused by the insertion anyway).
  const auto mid = std::stable_partition(idx.begin(), idx.end(), [&](std::uint32_t i) { return points[i].allFinite(); });
  const std::size_t n = static_cast<std::size_t>(mid - idx.begin());
  const std::vector<std::uint32_t> keys = hilbertKeys(points, finiteBox(points));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed;
  keyed.reserve(n);
  // Round boundaries from the end: [n/2, n), [n/4, n/2), … down to minRound.
  std::size_t hi = n;
  while (hi > 0) {
    const std::size_t lo = hi / 2 >= std::max<std::size_t>(minRound, 1) ? hi / 2 : 0;
    sortRange(keys, idx, lo, hi, keyed);
    hi = lo;
  }
  return idx;
}

}  // namespace aniso::del2d
