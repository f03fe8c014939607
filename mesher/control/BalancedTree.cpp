#include "mesher/control/BalancedTree.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesher/core/Error.h"

namespace aniso {
namespace {

constexpr int kMaxRootsPerAxis = 64;
constexpr int kMaxRoots = 4096;
constexpr double kMinRelativeExtent = 1e-6;

int pow3(int k) { return k == 0 ? 1 : 3 * pow3(k - 1); }

/// Static description of the 3^D virtual grid of a leaf.
template <int D>
struct GridTables {
  static constexpr int kNodes = BalancedTree<D>::kGridNodes;
  static constexpr int kSlots = BalancedTree<D>::kExtraSlots;
  std::array<std::array<int, D>, kNodes> digits{};
  std::array<int, kNodes> slotOfNode{};  ///< −1 for corners and the centre
  std::array<int, kNodes> cornerOfNode{};  ///< corner index, −1 if not a corner
  std::array<std::array<int, D>, kSlots> slotDigits{};
  std::array<std::array<int, 4>, kSlots> slotCorners{};
  std::array<int, kSlots> slotCornerCount{};

  GridTables() {
    int slot = 0;
    for (int g = 0; g < kNodes; ++g) {
      bool corner = true, centre = true;
      int cornerIndex = 0;
      for (int k = 0; k < D; ++k) {
        digits[g][k] = (g / pow3(k)) % 3;
        corner = corner && digits[g][k] != 1;
        centre = centre && digits[g][k] == 1;
        if (digits[g][k] == 2) cornerIndex |= 1 << k;
      }
      cornerOfNode[g] = corner ? cornerIndex : -1;
      slotOfNode[g] = -1;
      if (corner || centre) continue;
      slotOfNode[g] = slot;
      slotDigits[slot] = digits[g];
      int count = 0;
      for (int c = 0; c < (1 << D); ++c) {
        bool match = true;
        for (int k = 0; k < D; ++k)
          if (digits[g][k] != 1 && ((c >> k) & 1) != digits[g][k] / 2) match = false;
        if (match) slotCorners[slot][count++] = c;
      }
      slotCornerCount[slot] = count;
      ++slot;
    }
  }
};

template <int D>
const GridTables<D>& tables() {
  static const GridTables<D> t;
  return t;
}

template <int D>
std::string coordText(const std::array<std::int32_t, D>& c) {
  std::string s = "(";
  for (int k = 0; k < D; ++k) s += (k ? ", " : "") + std::to_string(c[k]);
  return s + ")";
}

[[noreturn]] void invalid(int dim, const std::string& what) {
  throw MeshingError(std::string(dim == 2 ? "quadtree" : "octree") + " control space invalid: " + what);
}

}  // namespace

template <int D>
std::size_t BalancedTree<D>::CoordHash::operator()(const ICoord& c) const {
  std::uint64_t h = 1469598103934665603ull;
  for (int k = 0; k < D; ++k) h = (h ^ static_cast<std::uint32_t>(c[k])) * 1099511628211ull;
  return static_cast<std::size_t>(h ^ (h >> 29));
}

template <int D>
BalancedTree<D>::BalancedTree(const Box<D>& box, int maxLevel) : maxLevel_(maxLevel) {
  if (box.empty() || !box.lo.allFinite() || !box.hi.allFinite())
    throw InputError("control space: the bounding box is empty or not finite");
  if (maxLevel < 0 || maxLevel > kResolution)
    throw InputError("control space: maximum level " + std::to_string(maxLevel) + " is outside [0, " +
                     std::to_string(kResolution) + "]");
  ext_ = box.size();
  const double big = ext_.maxCoeff();
  if (!(big > 0)) throw InputError("control space: the bounding box has zero size");
  lo_ = box.lo;
  for (int k = 0; k < D; ++k) {
    const double minExt = kMinRelativeExtent * big;
    if (ext_(k) < minExt) {
      lo_(k) -= 0.5 * (minExt - ext_(k));
      ext_(k) = minExt;
    }
  }
  // Near-cubic root cells: unit edge = smallest extent, coarsened until the counts fit.
  double unit = ext_.minCoeff();
  for (;;) {
    long total = 1;
    bool fits = true;
    for (int k = 0; k < D; ++k) {
      rootsPerAxis_[k] = std::max(1, static_cast<int>(std::lround(ext_(k) / unit)));
      fits = fits && rootsPerAxis_[k] <= kMaxRootsPerAxis;
      total *= rootsPerAxis_[k];
    }
    if (fits && total <= kMaxRoots) break;
    unit *= 1.25;
  }
  roots_ = 1;
  for (int k = 0; k < D; ++k) {
    rootSize_(k) = ext_(k) / rootsPerAxis_[k];
    cell_(k) = rootSize_(k) / double(1 << kResolution);
    limit_[k] = rootsPerAxis_[k] << kResolution;
    roots_ *= rootsPerAxis_[k];
  }
  for (int r = 0; r < roots_; ++r) {
    ICoord a;
    int rest = r;
    for (int k = 0; k < D; ++k) {
      a[k] = (rest % rootsPerAxis_[k]) << kResolution;
      rest /= rootsPerAxis_[k];
    }
    const int n = addNode(kNone, 0, a);
    for (int c = 0; c < kCorners; ++c) {
      ICoord p = a;
      for (int k = 0; k < D; ++k) p[k] += ((c >> k) & 1) << kResolution;
      const auto it = vmap_.find(p);
      corners_[n][c] = it != vmap_.end() ? it->second : addVertex(p);
    }
  }
  leaves_ = roots_;
}

template <int D>
Box<D> BalancedTree<D>::box() const {
  Box<D> b;
  b.lo = lo_;
  b.hi = lo_ + ext_;
  return b;
}

template <int D>
typename BalancedTree<D>::Vec BalancedTree<D>::nodeLo(int n) const {
  Vec p;
  for (int k = 0; k < D; ++k) p(k) = lo_(k) + ext_(k) * (double(anchor_[n][k]) / limit_[k]);
  return p;
}

template <int D>
typename BalancedTree<D>::Vec BalancedTree<D>::nodeSize(int n) const {
  return rootSize_ / double(1 << level_[n]);
}

template <int D>
typename BalancedTree<D>::Vec BalancedTree<D>::point(int v) const {
  Vec p;
  for (int k = 0; k < D; ++k) p(k) = lo_(k) + ext_(k) * (double(vcoord_[v][k]) / limit_[k]);
  return p;
}

template <int D>
typename BalancedTree<D>::ICoord BalancedTree<D>::toCoord(const Vec& x) const {
  ICoord c;
  for (int k = 0; k < D; ++k) {
    const double t = (x(k) - lo_(k)) / cell_(k);
    c[k] = t >= 0 ? (t < limit_[k] ? static_cast<std::int32_t>(t) : limit_[k] - 1) : 0;  // NaN → 0
  }
  return c;
}

template <int D>
bool BalancedTree<D>::inside(const ICoord& c) const {
  for (int k = 0; k < D; ++k)
    if (c[k] < 0 || c[k] >= limit_[k]) return false;
  return true;
}

template <int D>
int BalancedTree<D>::rootOf(const ICoord& c) const {
  int r = 0, mul = 1;
  for (int k = 0; k < D; ++k) {
    r += (c[k] >> kResolution) * mul;
    mul *= rootsPerAxis_[k];
  }
  return r;
}

template <int D>
int BalancedTree<D>::locateCoord(const ICoord& c, int upTo) const {
  int n = rootOf(c);
  for (int lev = 0; lev < upTo && firstChild_[n] != kNone; ++lev) {
    const int shift = kResolution - lev - 1;
    int idx = 0;
    for (int k = 0; k < D; ++k) idx |= ((c[k] >> shift) & 1) << k;
    n = firstChild_[n] + idx;
  }
  return n;
}

template <int D>
int BalancedTree<D>::locate(const Vec& x, Vec& local) const {
  const int n = locateCoord(toCoord(x), kResolution);
  const Vec lo = nodeLo(n), size = nodeSize(n);
  for (int k = 0; k < D; ++k) local(k) = std::clamp((x(k) - lo(k)) / size(k), 0.0, 1.0);
  if (!local.allFinite()) local.setConstant(0.5);
  return n;
}

template <int D>
int BalancedTree<D>::locate(const Vec& x) const {
  return locateCoord(toCoord(x), kResolution);
}

template <int D>
int BalancedTree<D>::leavesAround(int v, std::array<int, kCorners>& out) const {
  int count = 0;
  for (int o = 0; o < kCorners; ++o) {
    ICoord p = vcoord_[v];
    for (int k = 0; k < D; ++k) p[k] -= ((o >> k) & 1) ? 0 : 1;
    if (!inside(p)) continue;
    const int leaf = locateCoord(p, kResolution);
    if (std::find(out.begin(), out.begin() + count, leaf) == out.begin() + count) out[count++] = leaf;
  }
  return count;
}

template <int D>
std::vector<int> BalancedTree<D>::leaves() const {
  std::vector<int> result, stack;
  result.reserve(leaves_);
  for (int r = roots_ - 1; r >= 0; --r) stack.push_back(r);
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    if (firstChild_[n] == kNone) {
      result.push_back(n);
      continue;
    }
    for (int c = kCorners - 1; c >= 0; --c) stack.push_back(firstChild_[n] + c);
  }
  return result;
}

template <int D>
const std::array<int, D>& BalancedTree<D>::slotDigits(int s) {
  return tables<D>().slotDigits[s];
}

template <int D>
int BalancedTree<D>::slotCorners(int s, std::array<int, 4>& out) {
  out = tables<D>().slotCorners[s];
  return tables<D>().slotCornerCount[s];
}

template <int D>
int BalancedTree<D>::addVertex(const ICoord& c) {
  const int v = static_cast<int>(vcoord_.size());
  vcoord_.push_back(c);
  vmap_.emplace(c, v);
  return v;
}

template <int D>
int BalancedTree<D>::addNode(int parent, int level, const ICoord& anchor) {
  const int n = static_cast<int>(level_.size());
  firstChild_.push_back(kNone);
  parent_.push_back(parent);
  level_.push_back(static_cast<std::uint8_t>(level));
  anchor_.push_back(anchor);
  corners_.emplace_back();
  extraBlock_.push_back(kNone);
  depth_ = std::max(depth_, level);
  return n;
}

template <int D>
void BalancedTree<D>::setExtra(int n, int slot, int v) {
  if (extraBlock_[n] == kNone) {
    if (!freeBlocks_.empty()) {
      extraBlock_[n] = freeBlocks_.back();
      freeBlocks_.pop_back();
    } else {
      extraBlock_[n] = static_cast<int>(blocks_.size());
      blocks_.emplace_back();
    }
    blocks_[extraBlock_[n]].fill(kNone);
  }
  blocks_[extraBlock_[n]][slot] = v;
}

template <int D>
void BalancedTree<D>::freeExtras(int n) {
  if (extraBlock_[n] == kNone) return;
  freeBlocks_.push_back(extraBlock_[n]);
  extraBlock_[n] = kNone;
}

template <int D>
bool BalancedTree<D>::split(int n, const NewVertexFn& onVertex, const SplitFn& onSplit) {
  if (firstChild_[n] != kNone) return true;
  const int lev = level_[n];
  if (lev >= maxLevel_) return false;
  const std::int32_t size = std::int32_t(1) << (kResolution - lev), half = size / 2;
  const GridTables<D>& t = tables<D>();

  // 1. Balance: every neighbour region of the size of n must be at level ≥ lev.
  for (int o = 0; o < kGridNodes; ++o) {
    ICoord c = anchor_[n];
    bool self = true;
    for (int k = 0; k < D; ++k) {
      c[k] += (t.digits[o][k] - 1) * size;
      self = self && t.digits[o][k] == 1;
    }
    if (self || !inside(c)) continue;
    for (int m = locateCoord(c, lev); level_[m] < lev; m = locateCoord(c, lev))
      if (!split(m, onVertex, onSplit)) return false;
  }

  // 2. The 3^D grid vertices: corners, extras, or new ones (valued by the caller).
  std::array<int, kGridNodes> grid;
  std::array<int, kGridNodes> created;
  int createdCount = 0;
  for (int g = 0; g < kGridNodes; ++g) {
    if (t.cornerOfNode[g] >= 0) {
      grid[g] = corners_[n][t.cornerOfNode[g]];
      continue;
    }
    const int slot = t.slotOfNode[g];
    if (slot >= 0 && extra(n, slot) != kNone) {
      grid[g] = extra(n, slot);
      continue;
    }
    ICoord c = anchor_[n];
    Vec local;
    for (int k = 0; k < D; ++k) {
      c[k] += t.digits[g][k] * half;
      local(k) = 0.5 * t.digits[g][k];
    }
    const auto it = vmap_.find(c);
    if (it != vmap_.end()) {
      grid[g] = it->second;
      continue;
    }
    grid[g] = addVertex(c);
    if (slot >= 0) created[createdCount++] = g;
    onVertex(grid[g], n, local);
  }

  // 3. Children.
  const int first = nodeCount();
  for (int ch = 0; ch < kCorners; ++ch) {
    ICoord a = anchor_[n];
    for (int k = 0; k < D; ++k) a[k] += ((ch >> k) & 1) * half;
    const int child = addNode(n, lev + 1, a);
    for (int c = 0; c < kCorners; ++c) {
      int g = 0;
      for (int k = 0; k < D; ++k) g += (((ch >> k) & 1) + ((c >> k) & 1)) * pow3(k);
      corners_[child][c] = grid[g];
    }
  }
  firstChild_[n] = first;
  freeExtras(n);
  leaves_ += kCorners - 1;

  // 4. New vertices on the boundary of n are extras of the same-level neighbours.
  for (int i = 0; i < createdCount; ++i) {
    const int v = grid[created[i]];
    for (int o = 0; o < kCorners; ++o) {
      ICoord p = vcoord_[v];
      for (int k = 0; k < D; ++k) p[k] -= ((o >> k) & 1) ? 0 : 1;
      if (!inside(p)) continue;
      const int m = locateCoord(p, kResolution);
      if (m >= first && m < first + kCorners) continue;
      const std::int32_t mh = (std::int32_t(1) << (kResolution - level_[m])) / 2;
      int g = 0;
      for (int k = 0; k < D; ++k) g += ((vcoord_[v][k] - anchor_[m][k]) / mh) * pow3(k);
      if (t.slotOfNode[g] >= 0) setExtra(m, t.slotOfNode[g], v);
    }
  }
  onSplit(n);
  return true;
}

template <int D>
void BalancedTree<D>::validate() const {
  const GridTables<D>& t = tables<D>();
  std::vector<std::uint8_t> used(vcoord_.size(), 0);
  for (std::size_t v = 0; v < vcoord_.size(); ++v) {
    const auto it = vmap_.find(vcoord_[v]);
    if (it == vmap_.end() || it->second != int(v)) invalid(D, "vertex " + std::to_string(v) + " is not (uniquely) indexed");
  }
  if (vmap_.size() != vcoord_.size()) invalid(D, "the vertex index has stale entries");
  int leafCount = 0;
  for (int n = 0; n < nodeCount(); ++n) {
    const std::int32_t size = std::int32_t(1) << (kResolution - level_[n]);
    if (firstChild_[n] != kNone) {
      for (int ch = 0; ch < kCorners; ++ch) {
        const int c = firstChild_[n] + ch;
        bool ok = parent_[c] == n && level_[c] == level_[n] + 1;
        for (int k = 0; k < D; ++k) ok = ok && anchor_[c][k] == anchor_[n][k] + ((ch >> k) & 1) * size / 2;
        if (!ok) invalid(D, "child " + std::to_string(c) + " of node " + std::to_string(n) + " is misplaced");
      }
      if (extraBlock_[n] != kNone) invalid(D, "inner node " + std::to_string(n) + " keeps extra vertices");
      continue;
    }
    ++leafCount;
    const std::string name = "leaf " + std::to_string(n) + " at " + coordText<D>(anchor_[n]) + " level " +
                             std::to_string(level_[n]);
    for (int c = 0; c < kCorners; ++c) {
      ICoord p = anchor_[n];
      for (int k = 0; k < D; ++k) p[k] += ((c >> k) & 1) * size;
      const int v = corners_[n][c];
      if (v < 0 || v >= vertexCount() || vcoord_[v] != p) invalid(D, name + ": corner " + std::to_string(c) + " is wrong");
      used[v] = 1;
    }
    for (int g = 0; g < kGridNodes; ++g) {
      ICoord c = anchor_[n];
      bool self = true;
      for (int k = 0; k < D; ++k) {
        c[k] += (t.digits[g][k] - 1) * size;
        self = self && t.digits[g][k] == 1;
      }
      if (!self && inside(c) && level_[locateCoord(c, level_[n])] + 1 < level_[n])
        invalid(D, name + ": a neighbour is more than one level coarser (not balanced)");
      const int slot = t.slotOfNode[g];
      if (slot < 0) continue;
      ICoord q = anchor_[n];
      for (int k = 0; k < D; ++k) q[k] += t.digits[g][k] * (size / 2);
      const auto it = vmap_.find(q);
      const int expected = it == vmap_.end() ? kNone : it->second;
      if (extra(n, slot) != expected)
        invalid(D, name + ": extra slot " + std::to_string(slot) + " does not match the vertex at " + coordText<D>(q));
    }
  }
  if (leafCount != leaves_) invalid(D, "leaf count " + std::to_string(leaves_) + " != " + std::to_string(leafCount));
  for (std::size_t v = 0; v < used.size(); ++v)
    if (!used[v]) invalid(D, "vertex " + std::to_string(v) + " at " + coordText<D>(vcoord_[v]) + " is a corner of no leaf");
}

template class BalancedTree<2>;
template class BalancedTree<3>;

}  // namespace aniso
