#pragma once
// SeedOctree — choice of the starting tetrahedron of the location walk (thesis sec.
// 5.3.2). Each leaf keeps a reference to the tetrahedron whose representative point (its
// centroid, the thesis' default) is closest to the leaf centre among those sifted into it;
// the walk for a point starts from the reference of its leaf. Every sift increments the
// counter of the leaf it reaches; a leaf reaching `leafThreshold` (thesis default 1000)
// splits into 8 children, which inherit the reference. References to tets that have
// since been removed are detected when read (the slot is dead, or reused far away: the
// distance is recomputed from the current tet) — counters are never decreased.
//
// Use: after each insertion, update() with Inserter::newTets(); before the next one,
// seed(p) as the start. Pays off for unsorted insertion orders; with brioOrder the
// last created tet is already a good start.
#include <cstdint>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

class SeedOctree {
 public:
  /// Octree over `box` (non-empty); leafThreshold ≥ 1.
  explicit SeedOctree(const Box3& box, std::uint32_t leafThreshold = 1000, int maxDepth = 20);

  /// Sifts the live tet t (its centroid) to its leaf and makes it the leaf's reference if
  /// it is closer to the leaf centre than the current one (or the current one is dead).
  void update(const TetMesh& mesh, TetId t);
  /// A live tet to start the walk for p: the reference of p's leaf (points outside the box
  /// are clamped to it), or of the nearest ancestor having a live one; invalid if none.
  TetId seed(const TetMesh& mesh, const Vec3& p) const;

  std::size_t numNodes() const { return nodes_.size(); }
  std::size_t numLeaves() const;

 private:
  struct Node {
    Vec3 lo, hi;
    std::uint32_t child = kNone;  // index of the first of 8 children, or kNone for a leaf
    std::uint32_t best = kNone;   // reference tet
    std::uint32_t count = 0;
    std::uint32_t depth = 0;
  };
  std::uint32_t childOf(const Node& n, const Vec3& p) const;
  void split(std::uint32_t node);
  static Vec3 centroid(const TetMesh& mesh, TetId t);

  std::vector<Node> nodes_;
  std::uint32_t threshold_;
  int maxDepth_;
};

}  // namespace aniso::del3d
