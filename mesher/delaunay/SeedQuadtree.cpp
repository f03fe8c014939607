#include "mesher/delaunay/SeedQuadtree.h"

#include <cmath>

#include "mesher/core/Error.h"

namespace aniso::del2d {

SeedQuadtree::SeedQuadtree(const Box2& box, const SeedQuadtreeOptions& options) : options_(options) {
  if (box.empty() || !box.lo.allFinite() || !box.hi.allFinite())
    throw MeshingError("SeedQuadtree: the root box is empty or not finite");
  if (options.leafThreshold == 0 || options.sampleSize == 0)
    throw MeshingError("SeedQuadtree: leafThreshold and sampleSize must be at least 1");
  Node root;
  root.lo = box.lo;
  root.hi = box.hi;
  root.bucket = 0;
  nodes_.push_back(root);
  buckets_.emplace_back();
}

void SeedQuadtree::clear() {
  if (nodes_.empty()) return;
  Node root = nodes_[0];
  root.firstChild = kNone;
  root.bucket = 0;
  root.count = 0;
  nodes_.assign(1, root);
  buckets_.assign(1, {});
  maxDepthReached_ = 0;
}

std::size_t SeedQuadtree::numLeaves() const {
  std::size_t n = 0;
  for (const Node& node : nodes_) n += node.firstChild == kNone;
  return n;
}

void SeedQuadtree::insert(VertexId v, const Vec2& p) {
  if (nodes_.empty()) throw MeshingError("SeedQuadtree: insert into a tree without a box");
  std::uint32_t k = 0;
  for (;;) {
    ++nodes_[k].count;
    if (nodes_[k].firstChild == kNone) break;
    k = nodes_[k].firstChild + static_cast<std::uint32_t>(childOf(nodes_[k], p.x(), p.y()));
  }
  std::vector<Entry>& b = buckets_[nodes_[k].bucket];
  b.push_back({p.x(), p.y(), v.index});
  if (b.size() > options_.leafThreshold && nodes_[k].depth < options_.maxDepth) split(k);
}

void SeedQuadtree::split(std::uint32_t node) {
  const std::uint32_t first = static_cast<std::uint32_t>(nodes_.size());
  const Node parent = nodes_[node];
  const Vec2 c = 0.5 * (parent.lo + parent.hi);
  for (int q = 0; q < 4; ++q) {
    Node ch;
    ch.lo = Vec2((q & 1) ? c.x() : parent.lo.x(), (q & 2) ? c.y() : parent.lo.y());
    ch.hi = Vec2((q & 1) ? parent.hi.x() : c.x(), (q & 2) ? parent.hi.y() : c.y());
    ch.depth = parent.depth + 1;
    // Child 0 takes over the parent's bucket; the others get new ones.
    ch.bucket = q == 0 ? parent.bucket : static_cast<std::uint32_t>(buckets_.size());
    if (q != 0) buckets_.emplace_back();
    nodes_.push_back(ch);
  }
  if (parent.depth + 1 > maxDepthReached_) maxDepthReached_ = parent.depth + 1;
  std::vector<Entry> entries;
  entries.swap(buckets_[parent.bucket]);
  nodes_[node].firstChild = first;
  nodes_[node].bucket = kNone;
  for (const Entry& e : entries) {
    Node& ch = nodes_[first + static_cast<std::uint32_t>(childOf(parent, e.x, e.y))];
    buckets_[ch.bucket].push_back(e);
    ++ch.count;
  }
}

std::uint32_t SeedQuadtree::sampleLeaf(double x, double y) const {
  // Descend towards (x, y), remembering the deepest non-empty node on the way.
  std::uint32_t k = 0, lastNonEmpty = 0;
  while (nodes_[k].firstChild != kNone) {
    const std::uint32_t next = nodes_[k].firstChild + static_cast<std::uint32_t>(childOf(nodes_[k], x, y));
    if (nodes_[next].count == 0) break;
    k = next;
    lastNonEmpty = k;
  }
  k = lastNonEmpty;
  // From there, the non-empty child whose box is closest to (x, y), down to a leaf.
  while (nodes_[k].firstChild != kNone) {
    std::uint32_t best = kNone;
    double bestD = 0.0;
    for (std::uint32_t q = 0; q < 4; ++q) {
      const Node& ch = nodes_[nodes_[k].firstChild + q];
      if (ch.count == 0) continue;
      const double dx = std::fmax(0.0, std::fmax(ch.lo.x() - x, x - ch.hi.x()));
      const double dy = std::fmax(0.0, std::fmax(ch.lo.y() - y, y - ch.hi.y()));
      const double d = dx * dx + dy * dy;
      if (best == kNone || d < bestD) {
        best = nodes_[k].firstChild + q;
        bestD = d;
      }
    }
    k = best;
  }
  return k;
}

}  // namespace aniso::del2d
