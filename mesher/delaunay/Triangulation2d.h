#pragma once
// Triangulation2d — index-based storage of a planar triangulation: the kernel of the
// boundary-node triangulation and inner-node insertion of the surface mesher (thesis ch. 4,
// run in the parametric space of a patch) and of the background-mesh control space
// (sec. 3.4). STYLE.md §2 (flat arrays, typed handles), §3 (attributes beside topology).
//
// Layout: per triangle slot t, three vertex indices tv[3t..3t+2] in counter-clockwise
// order and three neighbours tn[3t..3t+2] — neighbour i lies across edge i, the edge
// opposite vertex i, i.e. (v[i+1], v[i+2]); kNone on the boundary — plus one flag byte.
// Freed slots form a free list threaded through the arrays: tv[3t] = kFreeMark,
// tn[3t] = next free slot. Per vertex: coordinates (Vec2, contiguous doubles handed
// directly to the exact predicates) and one incident live triangle (kNone when none).
//
// Flag byte per triangle: bits 0..2 mark edge i "constrained" (the Bowyer–Watson cavity
// never crosses it, flips never remove it, domain marking stops at it; both sides carry
// the bit); bits 3..5 are operator scratch marks (always 0 between operations).
//
// Construction (thesis sec. 4.4, "initial two triangles"): the given bounds grown by a
// margin, the four corners as vertices 0..3 (corner k: bit 0 → x max, bit 1 → y max),
// split along the diagonal 0–3 (or 1–2 when that one is the Delaunay diagonal for the
// option's transformation M) into two counter-clockwise triangles.
//
// The kernel owns a seeding quadtree of its vertices (SeedQuadtree.h, thesis sec. 4.4.1,
// brought up to date lazily when queried) used to start point location, and a scratch workspace reused by the operators so that
// an insertion does no heap allocation in the steady state.
//
// Operators, one per file (each checks, then changes): PointLocation.h (walk),
// InsertPoint.h (Bowyer–Watson with metric), EdgeFlip.h (flip and its criteria),
// DomainMarking.h (flood fill from constrained edges, removal), SpatialSort.h (insertion
// order), Validate2d.h (invariants). Not thread-safe for writes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "mesher/core/Assert.h"
#include "mesher/core/Types.h"
#include "mesher/delaunay/Handles.h"
#include "mesher/delaunay/SeedQuadtree.h"

namespace aniso::del2d {

struct Workspace2d;
class Triangulation2d;

namespace detail {
/// Base of an attribute array kept in step with a triangulation's slots (Attributes2d.h).
class AttributeSlot {
 public:
  virtual ~AttributeSlot() = default;
  virtual void grow(std::size_t n) = 0;          ///< at least n entries
  virtual void rebind(Triangulation2d* t) = 0;   ///< owner moved (or destroyed: nullptr)
};
}  // namespace detail

struct Triangulation2dOptions {
  /// The box is `bounds` grown on every side by margin × max(largest side of bounds,
  /// 1e-3 × (1 + largest |coordinate|)), so it has area even for degenerate bounds.
  double boxMargin = 0.1;
  /// Constant transformation M for which the initial two triangles are made Delaunay
  /// (the diagonal of the box is chosen by the in-circle test on M·x), so that
  /// Bowyer–Watson insertions with this M keep the whole triangulation M-Delaunay.
  Mat2 transform = Mat2::Identity();
  SeedQuadtreeOptions quadtree;
};

class Triangulation2d {
 public:
  static constexpr std::uint32_t kFreeMark = 0xFFFFFFFEu;
  static constexpr std::uint8_t kConstrainedMask = 0x07;
  static constexpr std::uint8_t kMarkA = 0x08;  ///< operator scratch bit ("in cavity")
  static constexpr std::uint8_t kMarkB = 0x10;  ///< operator scratch bit ("visited")
  static constexpr std::uint8_t kMarkC = 0x20;  ///< operator scratch bit
  static constexpr std::size_t kMaxTriangles = kFreeMark - 1;

  /// Initial triangulation of `bounds` (see above). Throws MeshingError when bounds is
  /// empty or not finite or the margin is not > 0.
  explicit Triangulation2d(const Box2& bounds, const Triangulation2dOptions& options = {});
  ~Triangulation2d();
  /// Copies topology, coordinates, flags and the quadtree; attached attributes stay with
  /// the source.
  Triangulation2d(const Triangulation2d& other);
  Triangulation2d& operator=(const Triangulation2d& other);
  /// Moves everything; attached attributes follow the moved-to object.
  Triangulation2d(Triangulation2d&& other) noexcept;
  Triangulation2d& operator=(Triangulation2d&& other) noexcept;

  // ---- vertices ----
  // Preconditions (ANISO_ASSERT, checked in Debug and sanitizer builds): a VertexId names an
  // existing vertex; a TriId given to a triangle accessor names a live triangle (free slots
  // are read only through nextFree), a local index is 0..2.
  std::size_t numVertices() const { return vtri_.size(); }
  const Vec2& point(VertexId v) const { return xy_[checked(v)]; }
  /// Pointer to the two coordinates of v (valid until the next addVertex).
  const double* coords(VertexId v) const { return xy_[checked(v)].data(); }
  /// One live triangle incident to v, or an invalid id if v is in none.
  TriId vertexTriangle(VertexId v) const { return TriId(vtri_[checked(v)]); }
  void setVertexTriangle(VertexId v, TriId t) {
    ANISO_ASSERT(!t.valid() || t.index < tf_.size());
    vtri_[checked(v)] = t.index;
  }
  /// The enlarged box and its corner vertices.
  const Box2& box() const { return box_; }
  const std::array<VertexId, 4>& corners() const { return corners_; }
  bool isCorner(VertexId v) const { return v.index < 4; }

  // ---- triangles ----
  /// Number of slots (live + free); TriIds range over [0, triangleSlots()).
  std::size_t triangleSlots() const { return tf_.size(); }
  std::size_t numTriangles() const { return live_; }
  bool isAlive(TriId t) const {
    return t.index < tf_.size() && tv_[3 * std::size_t{t.index}] != kFreeMark;
  }
  VertexId vertex(TriId t, int i) const { return VertexId(tv_[slot(t, i)]); }
  /// The three vertex indices of t (raw, for hot loops).
  const std::uint32_t* triVertices(TriId t) const { return &tv_[slot(t, 0)]; }
  TriId neighbour(TriId t, int i) const { return TriId(tn_[slot(t, i)]); }
  const std::uint32_t* triNeighbours(TriId t) const { return &tn_[slot(t, 0)]; }
  /// Local index (0..2) of v in t, or −1.
  int localIndex(TriId t, VertexId v) const;
  /// Local index i with neighbour(t, i) == u, or −1.
  int neighbourIndex(TriId t, TriId u) const;
  bool isConstrained(TriId t, int i) const { return (tf_[slot(t, i) / 3] >> i) & 1u; }
  /// Sets or clears the constrained bit of edge i of t and of the same edge in the
  /// neighbour (if any).
  void setConstrained(TriId t, int i, bool on);
  /// The live triangle t with the directed edge a→b (counter-clockwise in t) and the local
  /// index i of that edge, found by rotating around a; false when no triangle has it.
  bool findEdge(VertexId a, VertexId b, TriId& t, int& i) const;
  /// Constrains (or releases) the edge {a, b} on both sides; false when it is not an edge.
  bool setConstrainedEdge(VertexId a, VertexId b, bool on = true);

  // ---- low-level mutation (for operators; no geometric checks) ----
  /// Appends a vertex in no triangle (not yet in the seeding quadtree).
  VertexId addVertex(const Vec2& p);
  /// New triangle (a, b, c) — must be counter-clockwise — with no neighbours and no flags.
  /// Reuses the most recently freed slot. Throws MeshingError beyond kMaxTriangles.
  TriId createTriangle(VertexId a, VertexId b, VertexId c);
  /// Overwrites the vertices of the live triangle t (flags and neighbours unchanged).
  void setTriangle(TriId t, VertexId a, VertexId b, VertexId c);
  /// Puts t on the free list. Neighbours keep pointing at t: the caller relinks.
  void freeTriangle(TriId t);
  /// Sets the neighbour across edge i of t (one side only).
  void setNeighbour(TriId t, int i, TriId u) {
    ANISO_ASSERT(!u.valid() || u.index < tf_.size());
    tn_[slot(t, i)] = u.index;
    ++revision_;
  }
  /// Links edge i of t and edge j of u both ways.
  void link(TriId t, int i, TriId u, int j) {
    setNeighbour(t, i, u);
    setNeighbour(u, j, t);
  }
  /// Sets only this side's constrained bit of edge i of t.
  void setConstrainedBit(TriId t, int i, bool on) {
    ANISO_ASSERT(isAlive(t) && i >= 0 && i < 3);
    ++revision_;
    if (on) tf_[t.index] |= static_cast<std::uint8_t>(1u << i);
    else tf_[t.index] &= static_cast<std::uint8_t>(~(1u << i));
  }
  std::uint8_t flags(TriId t) const { return tf_[inRange(t)]; }
  void setMark(TriId t, std::uint8_t bit) { tf_[inRange(t)] |= bit; }
  void clearMark(TriId t, std::uint8_t bit) { tf_[inRange(t)] &= static_cast<std::uint8_t>(~bit); }
  bool hasMark(TriId t, std::uint8_t bit) const { return (tf_[inRange(t)] & bit) != 0; }

  // ---- acceleration and scratch ----
  /// The seeding quadtree of the vertices. Maintained lazily: vertices added since the
  /// last call are inserted now, so bulk insertions that start their walks elsewhere pay
  /// nothing for it.
  const SeedQuadtree& seeds() const;
  /// Scratch buffers of the operators (Workspace2d.h); not part of the state.
  Workspace2d& workspace() const { return *work_; }
  /// The most recently created live triangle (a good walk start for sorted input), or
  /// an invalid id.
  TriId lastTriangle() const { return isAlive(last_) ? last_ : TriId(); }

  /// Counter bumped by every topological or constraint change (not by scratch marks):
  /// lets a plan (check) detect that the triangulation changed before it is applied.
  std::uint64_t revision() const { return revision_; }

  // ---- whole triangulation ----
  void reserve(std::size_t vertices, std::size_t triangles);
  /// Head of the free list (kNone if empty) and successor of a free slot (for validate).
  std::uint32_t freeHead() const { return freeHead_; }
  std::uint32_t nextFree(TriId t) const {
    ANISO_ASSERT(t.index < tf_.size() && !isAlive(t));
    return tn_[3 * std::size_t{t.index}];
  }
  /// Bytes held by the arrays (capacities).
  std::size_t memoryBytes() const;

  // ---- attribute registry (Attributes2d.h) ----
  void attachTriangleAttribute(detail::AttributeSlot* a);
  void attachVertexAttribute(detail::AttributeSlot* a);
  void detachAttribute(detail::AttributeSlot* a);

 private:
  void rebindAttributes();
  /// v.index, asserted to name a vertex.
  std::uint32_t checked(VertexId v) const {
    ANISO_ASSERT(v.index < vtri_.size());
    return v.index;
  }
  /// t.index, asserted to name a slot (live or free).
  std::uint32_t inRange(TriId t) const {
    ANISO_ASSERT(t.index < tf_.size());
    return t.index;
  }
  /// 3·t + i, asserted to be entry i of a live triangle.
  std::size_t slot(TriId t, int i) const {
    ANISO_ASSERT(isAlive(t) && i >= 0 && i < 3);
    return 3 * std::size_t{t.index} + static_cast<std::size_t>(i);
  }

  std::vector<Vec2> xy_;             // 1 per vertex
  std::vector<std::uint32_t> vtri_;  // 1 per vertex
  std::vector<std::uint32_t> tv_;    // 3 per triangle slot
  std::vector<std::uint32_t> tn_;    // 3 per triangle slot
  std::vector<std::uint8_t> tf_;     // 1 per triangle slot
  std::uint32_t freeHead_ = kNone;
  std::size_t live_ = 0;
  std::uint64_t revision_ = 0;
  TriId last_;
  Box2 box_;
  std::array<VertexId, 4> corners_;
  mutable SeedQuadtree seeds_;
  mutable std::uint32_t seeded_ = 0;  ///< vertices [0, seeded_) are in seeds_
  std::unique_ptr<Workspace2d> work_;
  std::vector<detail::AttributeSlot*> triAttrs_, vertAttrs_;
};

}  // namespace aniso::del2d
