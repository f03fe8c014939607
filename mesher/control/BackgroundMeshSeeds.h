#pragma once
// VertexSeedOctree — starting elements for the location walks of BackgroundMesh3d
// (thesis sec. 3.4.5: "an additional quadtree/octree structure … for selection of good
// starting element"): an octree of the control vertices with buckets of at most
// `leafSize` vertices; a query returns the nearest vertex of the bucket of its leaf, whose
// incident tetrahedron (TetMesh::vertexTet) starts the walk.
//
// Why vertices and not the kernel's SeedOctree (which keeps tetrahedra): control vertices
// are never removed, so a reference never goes stale, while the tetrahedra referenced by
// a SeedOctree die during refinement and their slots are reused elsewhere — after a
// continuous adaptation its seeds were measured to leave walks of tens of steps. The
// kernel keeps vertexTet up to date, so a vertex always leads to a live tetrahedron.
// Points outside the root box are clamped to it. Const queries are thread-safe; insert is
// not. Flat arrays, one bucket vector per leaf.
#include <cstdint>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

class VertexSeedOctree {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  /// Throws MeshingError for an empty or non-finite box or leafSize 0.
  VertexSeedOctree(const Box3& box, std::uint32_t leafSize = 8, int maxDepth = 21);

  void insert(std::uint32_t vertex, const Vec3& p);
  /// The nearest vertex of the bucket of p's leaf; when that leaf is empty, a vertex of
  /// its deepest non-empty ancestor; kNone when the octree is empty.
  std::uint32_t nearest(const Vec3& p) const;
  std::size_t size() const { return size_; }

 private:
  struct Node {
    Vec3 lo, hi;
    std::uint32_t child = kNone;   ///< first of 8 consecutive children, or kNone (leaf)
    std::uint32_t bucket = kNone;  ///< leaf: index into buckets_
    std::uint32_t any = kNone;     ///< some vertex of the subtree
    int depth = 0;
  };
  struct Entry {
    Vec3 p;
    std::uint32_t v;
  };
  std::uint32_t childOf(const Node& n, const Vec3& p) const;
  void split(std::uint32_t node);

  std::vector<Node> nodes_;
  std::vector<std::vector<Entry>> buckets_;
  std::uint32_t leafSize_;
  int maxDepth_;
  std::size_t size_ = 0;
};

}  // namespace aniso
