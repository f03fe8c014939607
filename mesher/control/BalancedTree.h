#pragma once
// BalancedTree<D> — the topology of the quadtree (D = 2) / octree (D = 3) control space of
// sec. 3.3: a forest of equal root cells over a bounding box, recursively split in 2^D
// children, kept balanced after every split.
//
// Storage (STYLE.md 2, 3): flat arrays indexed by node and vertex id, no per-node heap
// objects. Children of a node are 2^D consecutive nodes. Every point of the tree is an
// integer coordinate on a fixed lattice of 2^kResolution steps per root cell, so vertices
// are found by exact integer keys and shared between the leaves that meet there.
//
// Balance ("2:1"): two leaves whose closures share at least one point differ by at most
// one level (face, edge and corner neighbours). split() first splits coarser neighbours
// recursively, so the property holds after every call.
//
// Vertices: a vertex is a point that is a corner of at least one leaf. A vertex lying on
// the boundary of a leaf without being one of its corners (the "hanging" vertex of a
// coarser neighbour: an edge midpoint, or in 3D a face centre) is recorded as an *extra*
// of that leaf, in one of its slots. The slots are the nodes of the leaf's virtual
// 3×3(×3) grid other than the corners and the centre (4 in 2D, 18 in 3D); with the balance
// property these are the only positions where a vertex can touch a leaf. The metric field
// (TreeControlSpace) interpolates extras hierarchically, which makes it continuous across
// leaves of different levels while every vertex keeps its own value.
//
// Child / corner numbering: bit k of the index is the offset along axis k.
// Thread safety: const methods are safe to call concurrently; split() is not.
#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

template <int D>
class BalancedTree {
  static_assert(D == 2 || D == 3, "BalancedTree<D> exists for D = 2 and D = 3");

 public:
  static constexpr int kCorners = 1 << D;                   ///< 4 / 8
  static constexpr int kGridNodes = D == 2 ? 9 : 27;        ///< 3^D virtual grid nodes
  static constexpr int kExtraSlots = kGridNodes - kCorners - 1;  ///< 4 / 18
  static constexpr int kResolution = 24;  ///< lattice bits per root cell = deepest level
  static constexpr int kNone = -1;
  using Vec = Eigen::Matrix<double, D, 1>;
  using ICoord = std::array<std::int32_t, D>;
  /// Called for every vertex a split creates, before the split changes anything else:
  /// `leaf` is the leaf being split and `local` ∈ [0,1]^D the vertex position in it.
  using NewVertexFn = std::function<void(int vertex, int leaf, const Vec& local)>;
  /// Called after a node has been split (its children exist).
  using SplitFn = std::function<void(int node)>;

  /// Root cells over `box` (near-cubic: at most 64 per axis and 4096 in all). Extents
  /// below 1e-6 of the largest are widened to that (a flat box still gets a volume).
  /// `maxLevel` ≤ kResolution bounds the depth. Throws InputError for an empty or
  /// non-finite box or a bad maxLevel.
  BalancedTree(const Box<D>& box, int maxLevel);

  // ---- geometry and topology ----
  Box<D> box() const;
  int maxLevel() const { return maxLevel_; }
  int nodeCount() const { return static_cast<int>(level_.size()); }
  int rootCount() const { return roots_; }
  int leafCount() const { return leaves_; }
  int vertexCount() const { return static_cast<int>(vcoord_.size()); }
  int depth() const { return depth_; }
  bool isLeaf(int n) const { return firstChild_[n] == kNone; }
  int firstChild(int n) const { return firstChild_[n]; }
  int parent(int n) const { return parent_[n]; }
  int level(int n) const { return level_[n]; }
  const std::array<int, kCorners>& corners(int n) const { return corners_[n]; }
  bool hasExtras(int n) const { return extraBlock_[n] != kNone; }
  /// Vertex in extra slot s of leaf n, or kNone.
  int extra(int n, int s) const { return extraBlock_[n] == kNone ? kNone : blocks_[extraBlock_[n]][s]; }
  Vec nodeLo(int n) const;
  Vec nodeSize(int n) const;
  Vec nodeCentre(int n) const { return nodeLo(n) + 0.5 * nodeSize(n); }
  Vec point(int v) const;
  const ICoord& vertexCoord(int v) const { return vcoord_[v]; }

  /// The leaf containing x (points outside the box: the leaf of the nearest box point),
  /// by direct descent from the root cell: O(depth). `local` gets x in leaf coordinates,
  /// clamped to [0, 1]^D.
  int locate(const Vec& x, Vec& local) const;
  int locate(const Vec& x) const;
  /// Distinct leaves whose closure contains vertex v (at most 2^D); returns the count.
  int leavesAround(int v, std::array<int, kCorners>& out) const;
  /// All leaves, in depth-first order.
  std::vector<int> leaves() const;

  // ---- virtual grid of a leaf ----
  /// Grid digits (0, 1, 2 per axis) of extra slot s.
  static const std::array<int, D>& slotDigits(int s);
  /// Corners whose average is the multilinear value at slot s (2 for an edge midpoint,
  /// 4 for a face centre); returns the count.
  static int slotCorners(int s, std::array<int, 4>& out);

  // ---- modification ----
  /// Splits leaf n into 2^D children, splitting coarser neighbours first (balance).
  /// Returns false (and changes nothing) when n is at maxLevel(); true if n is split
  /// afterwards (also when it already was).
  bool split(int n, const NewVertexFn& onVertex, const SplitFn& onSplit);

  /// Throws MeshingError naming the first violated invariant: child geometry and parent
  /// links, corner vertices, unique vertices, balance of every leaf against its 3^D − 1
  /// neighbour regions, every extra slot filled exactly when a vertex exists there, no
  /// vertex that is a corner of no leaf.
  void validate() const;

 private:
  struct CoordHash {
    std::size_t operator()(const ICoord& c) const;
  };
  ICoord toCoord(const Vec& x) const;
  bool inside(const ICoord& c) const;
  int rootOf(const ICoord& c) const;
  /// Descends from the root cell of c to the node containing c at level ≤ upTo.
  int locateCoord(const ICoord& c, int upTo) const;
  int addVertex(const ICoord& c);
  int addNode(int parent, int level, const ICoord& anchor);
  void setExtra(int n, int slot, int v);
  void freeExtras(int n);

  Vec lo_, ext_, rootSize_, cell_;
  std::array<std::int32_t, D> rootsPerAxis_{}, limit_{};
  int roots_ = 0, leaves_ = 0, depth_ = 0, maxLevel_ = 0;

  // nodes
  std::vector<std::int32_t> firstChild_, parent_;
  std::vector<std::uint8_t> level_;
  std::vector<ICoord> anchor_;
  std::vector<std::array<int, kCorners>> corners_;
  std::vector<std::int32_t> extraBlock_;
  std::vector<std::array<int, kExtraSlots>> blocks_;
  std::vector<std::int32_t> freeBlocks_;
  // vertices
  std::vector<ICoord> vcoord_;
  std::unordered_map<ICoord, int, CoordHash> vmap_;
};

extern template class BalancedTree<2>;
extern template class BalancedTree<3>;

}  // namespace aniso
