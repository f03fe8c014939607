#include "mesher/delaunay3d/SpatialSort.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "mesher/core/Error.h"

namespace aniso::del3d {
namespace {

constexpr std::uint64_t kNonFiniteKey = ~std::uint64_t{0};

// Cells per axis: about 2^(log2(n)/3 + 4), i.e. thousands of cells per point, which is as
// local as a finer curve for the walk and cheaper to compute.
int curveBits(std::size_t n) {
  int log2n = 0;
  while ((std::size_t{1} << log2n) < n && log2n < 63) ++log2n;
  return std::clamp(log2n / 3 + 4, 4, 21);
}

std::uint64_t splitmix(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// Hilbert keys of all points over their common bounding box.
std::vector<std::uint64_t> hilbertKeys(std::span<const Vec3> points) {
  Box3 box;
  for (const Vec3& p : points)
    if (p.allFinite()) box.add(p);
  std::vector<std::uint64_t> keys(points.size(), kNonFiniteKey);
  if (box.empty()) return keys;
  const int bits = curveBits(points.size());
  const double cells = static_cast<double>(1u << bits);
  Vec3 scale;
  for (int a = 0; a < 3; ++a) {
    const double ext = box.hi[a] - box.lo[a];
    scale[a] = ext > 0 ? cells / ext : 0.0;
  }
  const std::uint32_t maxCell = (1u << bits) - 1;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec3& p = points[k];
    if (!p.allFinite()) continue;
    std::uint32_t c[3];
    for (int a = 0; a < 3; ++a) {
      const double q = (p[a] - box.lo[a]) * scale[a];
      c[a] = std::min(maxCell, static_cast<std::uint32_t>(std::max(0.0, q)));
    }
    keys[k] = hilbertIndex(c[0], c[1], c[2], bits);
  }
  return keys;
}

// Sorts order[begin, end) by (key, index): deterministic, and the pairs sort in cache.
void sortRange(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end,
               const std::vector<std::uint64_t>& keys, std::vector<std::pair<std::uint64_t, std::uint32_t>>& buf) {
  buf.clear();
  for (std::size_t k = begin; k < end; ++k) buf.emplace_back(keys[order[k]], order[k]);
  std::sort(buf.begin(), buf.end());
  for (std::size_t k = begin; k < end; ++k) order[k] = buf[k - begin].second;
}

// The permutation 0..n−1 sorted by (key, index) with a stable least-significant-digit
// radix sort (the batches of the refinement: tens of thousands of keys, sorted thousands
// of times): the same order as sortRange on an identity `order`. Keys below 2^(3·bits),
// or kNonFiniteKey.
std::vector<std::uint32_t> radixOrder(const std::vector<std::uint64_t>& keys, int bits) {
  constexpr int kDigit = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigit;
  const std::uint64_t last = std::uint64_t{1} << (3 * bits);  // non-finite points, after all others
  std::vector<std::uint32_t> order(keys.size()), next(keys.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<std::uint32_t>(k);
  std::vector<std::size_t> count(kBuckets);
  for (int shift = 0; shift <= 3 * bits; shift += kDigit) {
    std::fill(count.begin(), count.end(), 0);
    auto digit = [&](std::uint32_t k) {
      const std::uint64_t key = keys[k] == kNonFiniteKey ? last : keys[k];
      return static_cast<std::size_t>((key >> shift) & (kBuckets - 1));
    };
    for (const std::uint32_t k : order) ++count[digit(k)];
    std::size_t sum = 0;
    for (std::size_t& c : count) sum += std::exchange(c, sum);
    for (const std::uint32_t k : order) next[count[digit(k)]++] = k;
    order.swap(next);
  }
  return order;
}

/// From this many points on, hilbertOrder sorts by radix.
constexpr std::size_t kRadixMin = 4096;

}  // namespace

// Skilling, "Programming the Hilbert curve" (AIP Conf. Proc. 707, 2004): axes to the
// transposed Hilbert index, then bit interleaving — run as a finite-state machine, one level
// (one bit per axis, most significant first) per step. Skilling's loop at level q acts on
// the bits below q only ("if (X[i] & q) X[0] ^= p; else swap the low bits of X[0] and
// X[i]", p = q − 1), so the working bits of every lower level are a signed permutation T of
// the raw bits: w_i = raw_{perm[i]} ^ mask_i, T updated by the level's operations, which
// depend on the level's working bits w only. The Gray decoding after the loop (X[1] ^= X[0],
// X[2] ^= X[1], then every level xor the parity t of X[2]'s bits above it) gives the digit
// (g0, g1, g2) ^ t with g = (w0, w0^w1, w0^w1^w2), t then toggled by g2. State (T, t):
// at most 48·2; tables built once by exploring from (identity, 0). SpatialSortTest checks
// it against the bit loop (hilbertIndexReference) for every bit count.
namespace {

struct HilbertMachine {
  static constexpr int kMaxStates = 96;
  std::uint8_t next[kMaxStates][8];
  std::uint8_t digit[kMaxStates][8];
  // Two levels per step: raw bits (upper level << 3 | lower level) -> two digits, state.
  std::uint8_t next2[kMaxStates][64];
  std::uint8_t digit2[kMaxStates][64];
  int states = 0;

  HilbertMachine() {
    struct State {
      std::array<int, 3> perm;
      std::array<int, 3> mask;
      int t;
      bool operator==(const State&) const = default;
    };
    std::vector<State> found{{{0, 1, 2}, {0, 0, 0}, 0}};
    for (std::size_t k = 0; k < found.size(); ++k) {
      for (int raw = 0; raw < 8; ++raw) {
        State s = found[k];
        int w[3];
        for (int i = 0; i < 3; ++i) w[i] = ((raw >> s.perm[i]) & 1) ^ s.mask[i];
        const int g0 = w[0], g1 = w[0] ^ w[1], g2 = w[0] ^ w[1] ^ w[2];
        const int d = ((g0 ^ s.t) << 2) | ((g1 ^ s.t) << 1) | (g2 ^ s.t);
        s.t ^= g2;
        for (int i = 0; i < 3; ++i) {
          if (w[i]) {
            s.mask[0] ^= 1;
          } else {
            std::swap(s.perm[0], s.perm[i]);
            std::swap(s.mask[0], s.mask[i]);
          }
        }
        std::size_t at = std::find(found.begin(), found.end(), s) - found.begin();
        if (at == found.size()) found.push_back(s);
        if (found.size() > kMaxStates) throw MeshingError("hilbertIndex: state machine too large");
        next[k][raw] = static_cast<std::uint8_t>(at);
        digit[k][raw] = static_cast<std::uint8_t>(d);
      }
    }
    states = static_cast<int>(found.size());
    for (int k = 0; k < states; ++k)
      for (int raw = 0; raw < 64; ++raw) {
        const int hi = raw >> 3, lo = raw & 7, mid = next[k][hi];
        digit2[k][raw] = static_cast<std::uint8_t>((digit[k][hi] << 3) | digit[mid][lo]);
        next2[k][raw] = next[mid][lo];
      }
  }
};

const HilbertMachine& hilbertMachine() {
  static const HilbertMachine m;
  return m;
}

}  // namespace

std::uint64_t hilbertIndex(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) {
  const HilbertMachine& h = hilbertMachine();
  std::uint64_t key = 0;
  int state = 0;
  int b = bits - 1;
  if (bits & 1) {  // an odd level first, then two at a time
    const int raw = static_cast<int>(((x >> b) & 1u) | (((y >> b) & 1u) << 1) | (((z >> b) & 1u) << 2));
    key = h.digit[state][raw];
    state = h.next[state][raw];
    --b;
  }
  for (; b > 0; b -= 2) {
    const int hi = static_cast<int>(((x >> b) & 1u) | (((y >> b) & 1u) << 1) | (((z >> b) & 1u) << 2));
    const int lo =
        static_cast<int>(((x >> (b - 1)) & 1u) | (((y >> (b - 1)) & 1u) << 1) | (((z >> (b - 1)) & 1u) << 2));
    const int raw = (hi << 3) | lo;
    key = (key << 6) | h.digit2[state][raw];
    state = h.next2[state][raw];
  }
  return key;
}

std::uint64_t hilbertIndexReference(std::uint32_t x, std::uint32_t y, std::uint32_t z, int bits) {
  std::uint32_t X[3] = {x, y, z};
  const std::uint32_t m = 1u << (bits - 1);
  for (std::uint32_t q = m; q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t set = 0u - ((X[i] & q) != 0 ? 1u : 0u);  // all ones when the bit is set
      const std::uint32_t t = (X[0] ^ X[i]) & p & ~set;          // 0 for i = 0
      X[0] ^= (p & set) | t;
      X[i] ^= t;
    }
  }
  for (int i = 1; i < 3; ++i) X[i] ^= X[i - 1];
  std::uint32_t t = 0;
  for (std::uint32_t q = m; q > 1; q >>= 1) t ^= (q - 1) & (0u - ((X[2] & q) != 0 ? 1u : 0u));
  for (int i = 0; i < 3; ++i) X[i] ^= t;
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < 3; ++i) key = (key << 1) | ((X[i] >> b) & 1u);
  return key;
}

std::vector<std::uint32_t> hilbertOrder(std::span<const Vec3> points) {
  if (points.size() >= 0xFFFFFFFFull) throw MeshingError("hilbertOrder: too many points");
  const std::vector<std::uint64_t> keys = hilbertKeys(points);
  if (points.size() >= kRadixMin) return radixOrder(keys, curveBits(points.size()));
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<std::uint32_t>(k);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> buf;
  sortRange(order, 0, order.size(), keys, buf);
  return order;
}

std::vector<std::uint32_t> brioOrder(std::span<const Vec3> points, std::uint64_t seed, double ratio,
                                     std::size_t minRound) {
  if (points.size() >= 0xFFFFFFFFull) throw MeshingError("brioOrder: too many points");
  if (!(ratio > 0 && ratio < 1)) throw MeshingError("brioOrder: ratio must be in (0, 1)");
  const std::vector<std::uint64_t> keys = hilbertKeys(points);
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<std::uint32_t>(k);
  std::uint64_t s = seed;
  for (std::size_t k = order.size(); k > 1; --k) std::swap(order[k - 1], order[splitmix(s) % k]);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> buf;
  buf.reserve(order.size());
  std::size_t end = order.size();
  while (end > 0) {
    std::size_t begin = end > minRound ? static_cast<std::size_t>(std::floor(static_cast<double>(end) * ratio)) : 0;
    if (begin < minRound / 2) begin = 0;
    sortRange(order, begin, end, keys, buf);
    end = begin;
  }
  return order;
}

}  // namespace aniso::del3d
