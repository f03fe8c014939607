#include "mesher/control/BackgroundMeshSeeds.h"

#include "mesher/core/Error.h"

namespace aniso {

VertexSeedOctree::VertexSeedOctree(const Box3& box, std::uint32_t leafSize, int maxDepth)
    : leafSize_(leafSize), maxDepth_(maxDepth) {
  if (box.empty() || !box.lo.allFinite() || !box.hi.allFinite() || leafSize == 0)
    throw MeshingError("VertexSeedOctree: empty or non-finite box, or leaf size 0");
  Node root;
  root.lo = box.lo;
  root.hi = box.hi;
  root.bucket = 0;
  nodes_.push_back(root);
  buckets_.emplace_back();
}

std::uint32_t VertexSeedOctree::childOf(const Node& n, const Vec3& p) const {
  const Vec3 mid = 0.5 * (n.lo + n.hi);
  return n.child + (p.x() >= mid.x() ? 1u : 0u) + (p.y() >= mid.y() ? 2u : 0u) + (p.z() >= mid.z() ? 4u : 0u);
}

void VertexSeedOctree::insert(std::uint32_t vertex, const Vec3& p) {
  std::uint32_t k = 0;
  for (;;) {
    if (nodes_[k].any == kNone) nodes_[k].any = vertex;
    if (nodes_[k].child == kNone) break;
    k = childOf(nodes_[k], p);
  }
  buckets_[nodes_[k].bucket].push_back({p, vertex});
  ++size_;
  if (buckets_[nodes_[k].bucket].size() > leafSize_ && nodes_[k].depth < maxDepth_) split(k);
}

void VertexSeedOctree::split(std::uint32_t node) {
  const std::uint32_t first = static_cast<std::uint32_t>(nodes_.size());
  const Node parent = nodes_[node];
  const Vec3 mid = 0.5 * (parent.lo + parent.hi);
  for (std::uint32_t c = 0; c < 8; ++c) {
    Node ch;
    for (int a = 0; a < 3; ++a) {
      const bool upper = (c >> a) & 1u;
      ch.lo[a] = upper ? mid[a] : parent.lo[a];
      ch.hi[a] = upper ? parent.hi[a] : mid[a];
    }
    ch.depth = parent.depth + 1;
    // Child 0 takes over the parent's bucket; the others get new ones.
    ch.bucket = c == 0 ? parent.bucket : static_cast<std::uint32_t>(buckets_.size());
    if (c != 0) buckets_.emplace_back();
    nodes_.push_back(ch);
  }
  std::vector<Entry> entries;
  entries.swap(buckets_[parent.bucket]);
  nodes_[node].child = first;
  nodes_[node].bucket = kNone;
  for (const Entry& e : entries) {
    Node& ch = nodes_[childOf(nodes_[node], e.p)];
    if (ch.any == kNone) ch.any = e.v;
    buckets_[ch.bucket].push_back(e);
  }
}

std::uint32_t VertexSeedOctree::nearest(const Vec3& p) const {
  const Vec3 q = p.cwiseMax(nodes_[0].lo).cwiseMin(nodes_[0].hi);
  std::uint32_t k = 0, fallback = nodes_[0].any;
  while (nodes_[k].child != kNone) {
    k = childOf(nodes_[k], q);
    if (nodes_[k].any != kNone) fallback = nodes_[k].any;
  }
  const std::vector<Entry>& b = buckets_[nodes_[k].bucket];
  std::uint32_t best = fallback;
  double bestD = -1;
  for (const Entry& e : b) {
    const double d = (e.p - q).squaredNorm();
    if (bestD < 0 || d < bestD) {
      best = e.v;
      bestD = d;
    }
  }
  return best;
}

}  // namespace aniso
