#pragma once
// Insertion of a point by the Bowyer–Watson cavity — the empty circumcircle criterion of
// thesis sec. 4.2.1 (Fig. 4.2) — with the metric introduced by coordinate transformation:
// the caller gives the (locally constant) transformation M of the point (P^M = M P,
// Metric.h / SurfaceMetric.h; identity by default) and every in-circle test is the exact
// predicate incircle(M a, M b, M c, M p) on the transformed doubles (sign corrected when
// det M < 0).
//
// Check, then change (STYLE.md §6):
//   planInsertion  locates p (PointLocation.h), grows the cavity from the containing
//                  triangle through neighbours with the in-circle test, never across a
//                  constrained edge, then makes it star-shaped from p on the real
//                  (untransformed) coordinates: every boundary edge (a, b) must satisfy
//                  orient2d(a, b, p) > 0; a cavity triangle owning a failing edge is
//                  dropped (with whatever that disconnects from the containing triangle)
//                  — the thesis' star-shape pruning — and so is any triangle around a
//                  vertex that would end up strictly inside the cavity. When the
//                  containing triangle itself has to be dropped (p on a constrained or
//                  boundary edge, or a degenerate transformation) the plan is Refused.
//                  Nothing of the triangulation changes.
//   applyInsertion replaces the planned cavity by the fan of triangles (p, a, b) over its
//                  boundary edges, keeps the constrained bits of those edges, updates
//                  vertex→triangle links (the seeding quadtree picks the
//                  new vertex up on its next query).
// A plan lives in the triangulation's workspace: apply it before any other operation.
//
// Star shape: with one constant M per insertion, the cavity grown from the containing
// triangle is star-shaped in exact arithmetic (every triangle entered through edge f has
// M p in the cap of its circumcircle beyond f, the caps beyond its other edges are
// disjoint from it, so p sees all its other edges strictly from inside), so the pruning
// only guards against rounded transformed coordinates. It is essential for the general
// form taking a ConflictTest, e.g. with the metric evaluated separately per triangle
// (thesis sec. 4.2.2, last paragraph), where cavities need not be star-shaped.
//
// Guarantees: the result is a valid triangulation (Validate2d.h) whatever M is; for the
// identity (or any constant M, evaluated on the same rounded transformed coordinates)
// and an unconstrained Delaunay triangulation the result is Delaunay again.
// Never corrupts the triangulation: every refusal happens before any change.
#include <cstddef>
#include <cstdint>

#include "mesher/core/Types.h"
#include "mesher/delaunay/PointLocation.h"
#include "mesher/delaunay/Triangulation2d.h"

namespace aniso::del2d {

enum class InsertStatus {
  Inserted,   ///< new vertex
  Duplicate,  ///< p equals an existing vertex (returned in `vertex`); nothing changed
  Outside,    ///< p lies outside the triangulation; nothing changed
  Refused,    ///< see `reason`; nothing changed
};

enum class RefuseReason {
  None,
  NotFinite,         ///< p has a non-finite coordinate
  BadTransform,      ///< M is not finite or det M == 0
  NotStarShaped,     ///< the containing triangle cannot be kept in a star-shaped cavity
                     ///< (p on a constrained edge or on the triangulation boundary)
};

struct InsertPlan {
  InsertStatus status = InsertStatus::Refused;
  RefuseReason reason = RefuseReason::None;
  Vec2 point = Vec2::Zero();
  LocateResult location;
  VertexId duplicate;            ///< for Duplicate
  std::size_t incircleTests = 0;  ///< statistics
  std::size_t pruned = 0;         ///< triangles dropped to keep the cavity star-shaped
  std::uint64_t revision = 0;     ///< Triangulation2d::revision() the plan was made on
  const void* workspace = nullptr;  ///< identity of the workspace holding the cavity
};

struct InsertResult {
  InsertStatus status = InsertStatus::Refused;
  RefuseReason reason = RefuseReason::None;
  VertexId vertex;             ///< the new vertex, or the existing one for Duplicate
  TriId triangle;              ///< one new triangle incident to `vertex` (Inserted)
  std::size_t cavitySize = 0;  ///< triangles removed
  std::size_t created = 0;     ///< triangles created (cavitySize + 2)
  std::size_t incircleTests = 0;
  std::size_t pruned = 0;
  std::size_t walkSteps = 0;
};

/// Whether a triangle belongs to the cavity of the point being inserted (the point is
/// known to the implementation). Called only for live triangles adjacent to the cavity.
class ConflictTest {
 public:
  virtual ~ConflictTest() = default;
  virtual bool inConflict(const Triangulation2d& tri, TriId t) const = 0;
};

/// An extra condition on the triangles (p, a, b) an insertion would make over the cavity
/// boundary edges a → b, enforced by the star-shape pruning exactly like orient2d > 0: a
/// cavity triangle owning an edge that fails it is dropped, and the plan is Refused
/// (NotStarShaped) when that is the containing triangle. E.g. the face mesher's fold guard
/// (surface/face/SurfaceLift.h): the new triangles must not be turned over on the surface.
class NewTriangleTest {
 public:
  virtual ~NewTriangleTest() = default;
  virtual bool accept(const Triangulation2d& tri, VertexId a, VertexId b) const = 0;
};

/// Check: plans the insertion of p with the transformation m, starting the walk at
/// `start` (invalid → seeding quadtree). The triangulation is unchanged.
InsertPlan planInsertion(Triangulation2d& tri, const Vec2& p, const Mat2& m = Mat2::Identity(),
                         TriId start = TriId(), const NewTriangleTest* extra = nullptr);
/// Check, general form: the cavity grows through the triangles for which `test` is true
/// (then star-shape pruning as above). A non-singular m is not needed here.
InsertPlan planInsertion(Triangulation2d& tri, const Vec2& p, const ConflictTest& test,
                         TriId start = TriId(), const NewTriangleTest* extra = nullptr);

/// Change: applies a plan made by planInsertion on the same, unchanged triangulation.
/// Plans that are not Inserted-ready return their status without changes. Throws
/// MeshingError when the triangulation changed since the plan was made.
InsertResult applyInsertion(Triangulation2d& tri, const InsertPlan& plan);

/// planInsertion + applyInsertion.
InsertResult insertPoint(Triangulation2d& tri, const Vec2& p, const Mat2& m = Mat2::Identity(),
                         TriId start = TriId());

}  // namespace aniso::del2d
