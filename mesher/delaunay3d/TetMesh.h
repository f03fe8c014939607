#pragma once
// TetMesh — index-based storage of a tetrahedralization (thesis ch. 5; STYLE.md §2, §3).
//
// Layout (geogram delaunay_3d): per tetrahedron t, four vertex indices tv[4t..4t+3] and four
// neighbour codes tn[4t..4t+3] in flat arrays, plus one flag byte. Neighbour i lies across
// face i (opposite vertex i) and is stored as the face code 4·u + j of the same face seen
// from the neighbour u (kNone on the hull). Every live tetrahedron is positively oriented
// (orient3d(v0,v1,v2,v3) > 0); validate() (Validate.h) checks this and the rest.
// Freed slots form a free list threaded through the arrays: tv[4t] = kFreeMark,
// tn[4t] = next free slot. Per-vertex attributes are separate vectors: coordinates
// (xyz, 3 doubles per vertex, handed directly to the exact predicates) and one incident
// tetrahedron per vertex (kNone while the vertex is in no tetrahedron).
//
// Flag byte per tet: bits 0..3 mark face i "constrained" (a fixed boundary face: the
// cavity search never crosses it, flips never remove it; both sides carry the bit),
// bits 4..5 are scratch marks of the operators (always 0 between operations).
//
// This is a low-level container: createTet/link/free do not check geometry. The
// operators (Inserter, flips, removeTets) keep the invariants. Not thread-safe for writes.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesher/core/Assert.h"
#include "mesher/core/Types.h"
#include "mesher/delaunay3d/Handles.h"

namespace aniso::del3d {

class TetMesh {
 public:
  static constexpr std::uint32_t kFreeMark = 0xFFFFFFFEu;
  static constexpr std::uint8_t kMarkA = 0x10;  ///< operator scratch bit (e.g. "in cavity")
  static constexpr std::uint8_t kMarkB = 0x20;  ///< operator scratch bit (e.g. "tested, not in")
  /// Largest number of tet slots: face codes 4·t + i must fit below kFreeMark.
  static constexpr std::size_t kMaxTets = (std::size_t{1} << 30) - 1;

  // Preconditions (ANISO_ASSERT, checked in Debug and sanitizer builds): a VertexId names an
  // existing vertex; a TetId given to a tet accessor names a live tet (free slots are read
  // only through nextFree), a local index is 0..3.

  // ---- vertices ----
  VertexId addVertex(const Vec3& p);
  std::size_t numVertices() const { return vtet_.size(); }
  /// Pointer to the three coordinates of v (valid until the next addVertex).
  const double* coords(VertexId v) const { return &xyz_[3 * std::size_t{checked(v)}]; }
  Vec3 point(VertexId v) const { const double* c = coords(v); return Vec3(c[0], c[1], c[2]); }
  /// One live tetrahedron incident to v, or an invalid id if v is in none.
  TetId vertexTet(VertexId v) const { return TetId(vtet_[checked(v)]); }
  void setVertexTet(VertexId v, TetId t) {
    ANISO_ASSERT(!t.valid() || t.index < tf_.size());
    vtet_[checked(v)] = t.index;
  }
  /// Moves vertex v to p. No check: the caller (smoothing, sec. 5.6.1) has verified that
  /// every incident tet stays positively oriented. Clears certifiedDelaunay(). Threads may
  /// move distinct vertices at once when the flag is cleared before (it is then only read).
  void movePoint(VertexId v, const Vec3& p) {
    double* c = &xyz_[3 * std::size_t{checked(v)}];
    c[0] = p.x(), c[1] = p.y(), c[2] = p.z();
    if (certified_) certified_ = false;
  }

  // ---- tetrahedra ----
  /// Number of slots (live + free); TetIds range over [0, tetSlots()).
  std::size_t tetSlots() const { return tf_.size(); }
  std::size_t numTets() const { return live_; }
  /// Slots the arrays hold without reallocating (reserve()).
  std::size_t tetCapacity() const { return tf_.capacity(); }
  bool isAlive(TetId t) const { return t.index < tf_.size() && tv_[4 * std::size_t{t.index}] != kFreeMark; }
  VertexId vertex(TetId t, int i) const { return VertexId(tv_[slot(t, i)]); }
  /// The four vertex indices of t (raw, for hot loops).
  const std::uint32_t* tetVertices(TetId t) const { return &tv_[slot(t, 0)]; }
  /// Local index (0..3) of v in t, or -1.
  int localIndex(TetId t, VertexId v) const;
  /// Face code (4·u + j) of the neighbour across face i, or kNone on the hull.
  std::uint32_t adjacentCode(TetId t, int i) const { return tn_[slot(t, i)]; }
  TetId neighbour(TetId t, int i) const { return codeTet(adjacentCode(t, i)); }
  bool isConstrained(TetId t, int i) const { return (tf_[slot(t, i) / 4] >> i) & 1u; }
  /// Sets or clears the constrained bit of face i of t and of the same face in the neighbour.
  void setConstrained(TetId t, int i, bool on);

  // ---- low-level mutation (for operators) ----
  /// New tet (a,b,c,d) — must be positively oriented — with no neighbours and no flags.
  /// Reuses the most recently freed slot. Throws MeshingError beyond kMaxTets.
  TetId createTet(VertexId a, VertexId b, VertexId c, VertexId d);
  /// Puts t on the free list. Neighbours keep their codes pointing at t: the caller relinks.
  void freeTet(TetId t);
  /// Sets the neighbour code of face i of t (one side only).
  void setAdjacentCode(TetId t, int i, std::uint32_t code) {
    ANISO_ASSERT(code == kNone || code / 4 < tf_.size());
    tn_[slot(t, i)] = code;
  }
  /// Links face i of t and face j of u both ways.
  void link(TetId t, int i, TetId u, int j) {
    setAdjacentCode(t, i, faceCode(u, j));
    setAdjacentCode(u, j, faceCode(t, i));
  }
  /// Sets only this side's constrained bit of face i of t.
  void setConstrainedBit(TetId t, int i, bool on) {
    ANISO_ASSERT(isAlive(t) && i >= 0 && i < 4);
    if (on) tf_[t.index] |= static_cast<std::uint8_t>(1u << i);
    else tf_[t.index] &= static_cast<std::uint8_t>(~(1u << i));
  }
  std::uint8_t flags(TetId t) const { return tf_[inRange(t)]; }
  /// Hints the memory of t's neighbour codes and flags into the cache (hot loops: the
  /// cavity search asks for them one dependent load after another).
  void prefetchAdjacency(TetId t) const {
    __builtin_prefetch(&tn_[4 * std::size_t{t.index}]);
    __builtin_prefetch(&tf_[t.index]);
  }
  /// The same for t's vertex indices, and (once those are at hand) its vertices' coordinates.
  void prefetchVertices(TetId t) const { __builtin_prefetch(&tv_[4 * std::size_t{t.index}]); }
  void prefetchCoords(TetId t) const {
    const std::uint32_t* v = tetVertices(t);
    for (int i = 0; i < 4; ++i) __builtin_prefetch(&xyz_[3 * std::size_t{v[i]}]);
  }
  void setMark(TetId t, std::uint8_t bit) { tf_[inRange(t)] |= bit; }
  void clearMark(TetId t, std::uint8_t bit) { tf_[inRange(t)] &= static_cast<std::uint8_t>(~bit); }
  bool hasMark(TetId t, std::uint8_t bit) const { return (tf_[inRange(t)] & bit) != 0; }

  // ---- certified Delaunay property ----
  /// True while the mesh is known to be Delaunay for the identity metric with no
  /// constrained face: set by createEnclosingBox (no transform), kept by Inserter
  /// insertions with the identity that needed no pruning, cleared by setConstrained(on),
  /// replaceTets (flips), insertions with a transform or with pruning, and clear().
  /// The low-level mutators below leave it alone: code using them directly must clear it.
  /// Inserter uses it to skip the star-shape orient3d of faces shared with tested,
  /// non-conflicting tets, which the empty-sphere property makes redundant.
  bool certifiedDelaunay() const { return certified_; }
  void setCertifiedDelaunay(bool on) { certified_ = on; }

  // ---- whole mesh ----
  void reserve(std::size_t vertices, std::size_t tets);
  /// Renumbers vertices and tets in place (memory locality for the phases that walk stars,
  /// rings and tets in index order). newVertex[v]: the new number of vertex v, a permutation
  /// of 0..numVertices()−1; newTet[t]: the new number of the live tet in slot t, a
  /// permutation onto 0..numTets()−1 (kNone for free slots). Geometry, adjacency,
  /// constrained faces and the certified flag are unchanged; the free slots are dropped (no
  /// free list afterwards). Throws MeshingError, before any change, on a bad permutation.
  void renumber(const std::vector<std::uint32_t>& newVertex, const std::vector<std::uint32_t>& newTet);
  void clear();
  /// Bytes held by the arrays (capacities, not sizes): the memory cost of the kernel.
  std::size_t memoryBytes() const;
  /// Head of the free list (kNone if empty) and successor of a free slot (for validate()).
  std::uint32_t freeHead() const { return freeHead_; }
  std::uint32_t nextFree(TetId t) const {
    ANISO_ASSERT(t.index < tf_.size() && !isAlive(t));
    return tn_[4 * std::size_t{t.index}];
  }
  /// Raw coordinate array (3 per vertex).
  const std::vector<double>& xyz() const { return xyz_; }

 private:
  /// v.index, asserted to name a vertex.
  std::uint32_t checked(VertexId v) const {
    ANISO_ASSERT(v.index < vtet_.size());
    return v.index;
  }
  /// t.index, asserted to name a slot (live or free).
  std::uint32_t inRange(TetId t) const {
    ANISO_ASSERT(t.index < tf_.size());
    return t.index;
  }
  /// 4·t + i, asserted to be entry i of a live tet.
  std::size_t slot(TetId t, int i) const {
    ANISO_ASSERT(isAlive(t) && i >= 0 && i < 4);
    return 4 * std::size_t{t.index} + static_cast<std::size_t>(i);
  }

  std::vector<double> xyz_;          // 3 per vertex
  std::vector<std::uint32_t> vtet_;  // 1 per vertex
  std::vector<std::uint32_t> tv_;    // 4 per tet slot
  std::vector<std::uint32_t> tn_;    // 4 per tet slot
  std::vector<std::uint8_t> tf_;     // 1 per tet slot
  std::uint32_t freeHead_ = kNone;
  std::size_t live_ = 0;
  bool certified_ = false;
};

}  // namespace aniso::del3d
