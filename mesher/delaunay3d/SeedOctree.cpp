#include "mesher/delaunay3d/SeedOctree.h"

#include "mesher/core/Error.h"

namespace aniso::del3d {

SeedOctree::SeedOctree(const Box3& box, std::uint32_t leafThreshold, int maxDepth)
    : threshold_(leafThreshold), maxDepth_(maxDepth) {
  if (box.empty()) throw MeshingError("SeedOctree: empty box");
  if (leafThreshold == 0) throw MeshingError("SeedOctree: leaf threshold must be >= 1");
  Node root;
  root.lo = box.lo;
  root.hi = box.hi;
  nodes_.push_back(root);
}

Vec3 SeedOctree::centroid(const TetMesh& mesh, TetId t) {
  const std::uint32_t* v = mesh.tetVertices(t);
  return 0.25 * (mesh.point(VertexId(v[0])) + mesh.point(VertexId(v[1])) + mesh.point(VertexId(v[2])) +
                 mesh.point(VertexId(v[3])));
}

std::uint32_t SeedOctree::childOf(const Node& n, const Vec3& p) const {
  const Vec3 mid = 0.5 * (n.lo + n.hi);
  return n.child + (p.x() >= mid.x() ? 1u : 0u) + (p.y() >= mid.y() ? 2u : 0u) + (p.z() >= mid.z() ? 4u : 0u);
}

void SeedOctree::split(std::uint32_t node) {
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
    ch.best = parent.best;
    ch.depth = parent.depth + 1;
    nodes_.push_back(ch);
  }
  nodes_[node].child = first;
}

void SeedOctree::update(const TetMesh& mesh, TetId t) {
  if (!mesh.isAlive(t)) return;
  const Vec3 c = centroid(mesh, t);
  std::uint32_t k = 0;
  while (nodes_[k].child != kNone) k = childOf(nodes_[k], c);
  Node& leaf = nodes_[k];
  const Vec3 centre = 0.5 * (leaf.lo + leaf.hi);
  const TetId cur(leaf.best);
  if (!mesh.isAlive(cur) || (c - centre).squaredNorm() < (centroid(mesh, cur) - centre).squaredNorm())
    leaf.best = t.index;
  if (++leaf.count >= threshold_ && static_cast<int>(leaf.depth) < maxDepth_) split(k);
}

TetId SeedOctree::seed(const TetMesh& mesh, const Vec3& p) const {
  const Vec3 q = p.cwiseMax(nodes_[0].lo).cwiseMin(nodes_[0].hi);
  TetId found;
  std::uint32_t k = 0;
  for (;;) {
    const Node& n = nodes_[k];
    if (mesh.isAlive(TetId(n.best))) found = TetId(n.best);
    if (n.child == kNone) break;
    k = childOf(n, q);
  }
  return found;
}

std::size_t SeedOctree::numLeaves() const {
  std::size_t n = 0;
  for (const Node& node : nodes_)
    if (node.child == kNone) ++n;
  return n;
}

}  // namespace aniso::del3d
