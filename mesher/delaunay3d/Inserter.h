#pragma once
// Inserter — incremental Bowyer–Watson insertion of one point (thesis sec. 5.2.1, the
// criterion of empty circumsphere), with the robustness rules of the thesis:
//
//  1. Locate the containing tetrahedron K_c (Locate.h).
//  2. Cavity C_V: K_c (and, when the point lies on a face or an edge of K_c, the other
//     tetrahedra containing it) plus every tetrahedron reached through non-constrained
//     faces by depth-first search whose circumsphere STRICTLY contains the point. The
//     in-sphere test is exact (predicates::insphere) on transformed coordinates:
//     insphere(M a, M b, M c, M d, M p) for the caller's 3×3 matrix M (identity by
//     default; the metric of the control space at the point, held constant, sec. 5.2.1).
//     With cacheSpheres() and the identity, the cached circumsphere of the tet decides first
//     when its error bound certifies the sign (Circumsphere.h), the exact test otherwise.
//  3. Pruning: every cavity face must form with the point a positively oriented tet
//     (exact orient3d on the untransformed coordinates; skipped for faces shared with a
//     tested non-conflicting tet when the mesh is TetMesh::certifiedDelaunay() and M = I,
//     where the empty-sphere property guarantees it, or, with cacheSpheres(), when the
//     cached spheres certify that this pair of tets is locally Delaunay). A tet owning a
//     face that fails is dropped from the cavity, and so are tets that would delete a
//     constrained face or leave a vertex inside the cavity (a "stranded" vertex — impossible when every
//     cavity tet strictly contains the point in its circumsphere, so only a guard against
//     the rounding of M·x); this repeats until stable. If K_c itself must be dropped, the
//     insertion is refused and the mesh is untouched. (The thesis also drops tets whose
//     new tet would have a volume below ϵ_M; here the exact sign is the criterion and
//     quality is left to the caller.)
//  4. The cavity is replaced by one tet per cavity face joined to the point; the new
//     tets are linked to each other through the edges of the cavity faces: a triangular
//     table indexed by the pair of local vertex numbers (a hash table of edges for very
//     large cavities), reset by a time stamp, so nothing is cleared per insertion.
//
// The result is always a valid mesh: a refused, duplicate, outside or pointless point
// leaves it unchanged. With a constant M, no constrained faces and a mesh that was
// Delaunay for M (e.g. from createEnclosingBox with the same M), the mesh stays Delaunay
// for M; M is applied in floating point (TransformPoint.h), so "Delaunay for M" means
// for the rounded transformed points, the same ones validate() checks.
// Scratch buffers live in the Inserter and are reused: no heap allocation per insertion
// once they have grown to the largest cavity. One Inserter per mesh; not thread-safe.
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/delaunay3d/Circumsphere.h"
#include "mesher/delaunay3d/Locate.h"
#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

enum class InsertStatus {
  Inserted,   ///< a new vertex was created (InsertResult::vertex)
  Duplicate,  ///< the point equals an existing vertex (InsertResult::vertex); nothing changed
  Outside,    ///< the point is outside the mesh (see LocateStatus::Outside); nothing changed
  Refused,    ///< the containing tet could not be kept in a star-shaped cavity; nothing changed
  Pointless,  ///< InsertOptions::mustRemove would survive the insertion; nothing changed
};

struct InsertOptions {
  /// A live tet to begin the walk from (invalid: the last tet created by this Inserter,
  /// else any live tet), e.g. from SeedOctree::seed.
  TetId start;
  /// The matrix M of the in-sphere test (nullptr = identity), typically the symmetric
  /// positive-definite Metric3d::matrix() at the point.
  const Mat3* transform = nullptr;
  /// Refinement mode (thesis sec. 5.2.1): cancel the insertion, status Pointless, unless
  /// this tet is in the final cavity (the point was meant to improve it).
  TetId mustRemove;
  /// The caller's locate() of this very point in the current mesh, if it has one (the walk
  /// is then not repeated; `start` is ignored).
  const LocateResult* located = nullptr;
};

struct InsertResult {
  InsertStatus status = InsertStatus::Refused;
  VertexId vertex;               ///< new vertex (Inserted) or the coinciding one (Duplicate)
  TetId tet;                     ///< a new tet incident to the vertex, or the located tet
  std::uint32_t cavityTets = 0;  ///< tetrahedra removed (Inserted)
  std::uint32_t walkSteps = 0;   ///< tetrahedra visited by the location walk
};

class Inserter {
 public:
  explicit Inserter(TetMesh& mesh, std::uint32_t seed = 0x2545F491u);

  /// Inserts p (see InsertOptions).
  InsertResult insert(const Vec3& p, const InsertOptions& options);
  InsertResult insert(const Vec3& p, TetId start = TetId(), const Mat3* transform = nullptr) {
    return insert(p, InsertOptions{start, transform, TetId(), nullptr});
  }

  /// Tets created by the last successful insertion (they may reuse freed slots).
  std::span<const TetId> newTets() const { return newTets_; }
  /// Slots freed by the last successful insertion (before the new tets reused them).
  std::span<const TetId> removedTets() const { return removed_; }
  /// From now on keeps the circumsphere of every tet (Circumsphere.h): computed here for the
  /// live tets, and at each insertion for the new ones; insertions with the identity metric
  /// test them first and evaluate the exact insphere only when the cached filter cannot
  /// certify. Valid only while the mesh is changed by this Inserter alone (the refinement).
  void cacheSpheres();
  /// The cached circumsphere of live tet t (cacheSpheres() called).
  const CachedSphere& sphere(TetId t) const { return spheres_[t.index]; }
  /// Cumulative counters since construction.
  std::uint64_t inSphereTests() const { return inSphereTests_; }
  std::uint64_t refusals() const { return refusals_; }

 private:
  struct BoundaryFace {
    std::uint32_t v[4];      // vertices of the new tet (the cavity tet's, with p at slot `face`)
    std::uint32_t outer;     // neighbour code across the cavity face (kNone on the hull)
    std::uint32_t link[4];   // per local face j != face: index 4·k + j' of the matching new face
    std::uint32_t l[4];      // local numbers (vmark_) of the vertices
    std::uint8_t face;       // local index of the point in the new tet
    bool constrained;
  };
  struct EdgeSlot {  // hashed edge (large cavities)
    std::uint32_t stamp = 0, a = 0, b = 0, ref = 0;
  };
  struct PairSlot {  // edge by local vertex numbers (small cavities)
    std::uint32_t stamp = 0, ref = 0;
  };

  bool inConflict(TetId t) const;
  const double* transformed(std::uint32_t v) const;
  void seedCavity(const LocateResult& loc);
  void growCavity();
  bool collectBoundary();
  bool visibleByPower(const std::uint32_t* tv, int i, std::uint32_t code, bool skip) const;
  bool pruneCavity();
  bool matchEdges();
  bool matchEdgesHashed();
  bool link(std::uint32_t& slotRef, std::size_t k, int j);
  void commit();
  void clearMarks();
  void nextStamp();

  TetMesh& mesh_;
  std::uint32_t rng_;
  TetId last_;
  double p_[3] = {0, 0, 0};
  double mp_[3] = {0, 0, 0};
  const Mat3* m_ = nullptr;
  TetId located_;

  std::vector<TetId> cavity_;
  std::vector<TetId> rejected_;
  std::vector<BoundaryFace> boundary_;  // first nb_ entries used
  std::size_t nb_ = 0;
  std::vector<EdgeSlot> edges_;
  std::vector<PairSlot> pairs_;
  std::vector<TetId> newTets_;
  std::vector<TetId> removed_;
  std::vector<TetId> ring_;
  struct VertexMark {  // per vertex: its number among the cavity vertices, valid at stamp
    std::uint32_t stamp = 0, local = 0;
  };
  std::vector<VertexMark> vmark_;
  mutable std::vector<double> mxyz_;            // per vertex transformed coordinates (M != I)
  mutable std::vector<std::uint32_t> mstamp_;   // per vertex stamp of mxyz_
  std::uint32_t stamp_ = 0;
  std::uint32_t cavityVertices_ = 0;
  std::vector<CachedSphere> spheres_;  // per tet slot, while spheresOn_
  bool spheresOn_ = false;
  bool powerTest_ = false;  // collectBoundary may use visibleByPower
  bool certified_ = false;  // mesh certified Delaunay and identity metric: see collectBoundary
  mutable std::uint64_t inSphereTests_ = 0;
  std::uint64_t refusals_ = 0;
};

}  // namespace aniso::del3d
