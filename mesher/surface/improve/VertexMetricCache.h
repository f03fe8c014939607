#pragma once
// VertexMetricCache — the per-pass state shared by the operators of the triangle mesh
// improvement (thesis sec. 4.6, alg. 4.2): the control space is evaluated once per vertex
// at the start of a pass and the result is reused by every operator of that pass (the
// thesis counts control-space calls; moving a vertex does not re-evaluate it).
//
// Per vertex used by a live triangle it holds
//   - S_v, the symmetric form of the surface transformation M = M_s M_p (eq. 2.9):
//     S = (MᵀM)^{1/2}, so |S x| = |M x| for every vector x (S and M differ by a rotation of
//     the metric space, to which lengths, angles and η_M are blind), and S_v⁻¹;
//   - the local metric gradation g_v = max over the neighbours P of δ_M(S_v, S_P)
//     (MetricComparison.h, eq. 2.24–2.25) — the thesis' "metric gradation ratio" of
//     sec. 4.6.1–4.6.2, measured on the mesh since a ControlSpace2d does not expose it;
//   - the ideal degree (number of edges) of the vertex: 6 inside; on the border of the
//     triangulation round(θ / 60°) + 1 with θ the metric-space angle of its star (4 on a
//     straight border), at least 2;
//   - whether it may move: used, not flagged fixed, its star closed (not on the border of
//     the triangulation), not on a constrained edge, its metric usable, and not in a
//     triangle touching a degenerate boundary edge (below).
// Degenerate boundary edges (poles): a constrained edge whose metric length is below
// kDegenerateEdgeLength (|S_a e| and |S_b e| both; a pole has length only through the g_min
// guard of M_p), or with an endpoint whose metric is unusable. At a pole several boundary
// vertices are one point in 3D, which the metric, linear around each vertex, cannot
// represent: the triangles touching such an edge's endpoints are left exactly as the face
// mesher made them — frozen() is true for them, the operators never flip an edge of a
// frozen triangle, and their vertices never move — else flips could connect one interior
// vertex to two pole vertices across an edge, which folds (duplicates) triangles in 3D.
//
// A metric is unusable when M is not finite or singular; such a vertex is held fixed and
// takes the metric of its first usable neighbour met visiting the triangles by index (the
// identity when it has none).
//
// Also here: the n-point metric of a group of vertices (eq. 2.18 on the cached S, used for
// a triangle or a quadrilateral), the closed star walk, and the vertex move.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/core/Types.h"
#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/surface/face/SurfaceLift.h"

namespace aniso::improve {

using del2d::Triangulation2d;
using del2d::TriId;
using del2d::VertexId;

/// Metric length below which a constrained edge counts as degenerate (a pole).
inline constexpr double kDegenerateEdgeLength = 1e-2;

class VertexMetricCache {
 public:
  /// Evaluates cs at every vertex of a live triangle and classifies the vertices (see
  /// above). `fixed` has one entry per vertex (non-zero: never moves); throws MeshingError
  /// when fixed.size() < tri.numVertices(). Reuses its arrays (no allocation once grown).
  void update(const Triangulation2d& tri, const ControlSpace2d& cs, std::span<const std::uint8_t> fixed);

  /// Number of vertices covered (tri.numVertices() at the last update).
  std::size_t size() const { return flags_.size(); }
  bool used(VertexId v) const { return flags_[v.index] & kUsed; }
  bool movable(VertexId v) const { return flags_[v.index] & kMovable; }
  /// The metric could not be used (see above).
  bool unusableMetric(VertexId v) const { return flags_[v.index] & kBadMetric; }
  const Mat2& transform(VertexId v) const { return s_[v.index]; }
  const Mat2& inverse(VertexId v) const { return inv_[v.index]; }
  double gradation(VertexId v) const { return grad_[v.index]; }
  int idealDegree(VertexId v) const { return ideal_[v.index]; }

  /// Whether the live triangle t touches an endpoint of a degenerate boundary edge (see
  /// above): its edges must not be flipped.
  bool frozen(const Triangulation2d& tri, TriId t) const;
  /// Whether edge i of t may not be flipped because t or its neighbour there is frozen.
  bool edgeFrozen(const Triangulation2d& tri, TriId t, int i) const {
    const TriId u = tri.neighbour(t, i);
    return frozen(tri, t) || (u.valid() && frozen(tri, u));
  }
  bool onDegenerateEdge(VertexId v) const { return flags_[v.index] & kDegenerate; }

  /// The metric of a group of 1 ≤ n ≤ 4 vertices (a triangle, a quadrilateral): S when all n cached S are bit-identical
  /// (a constant metric stays exact), else (Σ S_i⁻¹ / n)⁻¹ (eq. 2.18), summed in
  /// increasing vertex order so that the result does not depend on the order given.
  Mat2 blend(const VertexId* v, int n) const;

  /// The fold guard (face/SurfaceLift.h): the improvement operators make no triangle that
  /// is turned over on the surface. Null (the default) or inactive: every test passes.
  void setLift(const face::SurfaceLift* lift) { lift_ = lift; }
  /// Both triangles of the flip are upright on the surface.
  bool flipUpright(const Triangulation2d& tri, const del2d::FlipPlan& plan) const {
    return !lift_ || lift_->flipUpright(tri, plan);
  }
  /// The triangle (a, b, c) is upright.
  bool triangleUpright(const Triangulation2d& tri, VertexId a, VertexId b, VertexId c) const {
    return !lift_ || lift_->upright(tri, a, b, c);
  }
  /// Every fan triangle (x, ring[k], ring[k+1]) (cyclically) is upright with a vertex at
  /// (u, v) x.
  bool fanUpright(const Triangulation2d& tri, const Vec2& x, std::span<const VertexId> ring) const;

 private:
  static constexpr std::uint8_t kUsed = 1, kMovable = 2, kOpen = 4, kConstrained = 8, kBadMetric = 16,
                                kSubstituted = 32, kDegenerate = 64, kNearDegenerate = 128;
  void classifyTopology(const Triangulation2d& tri);
  void substituteUnusable(const Triangulation2d& tri);
  void measureNeighbourhoods(const Triangulation2d& tri);
  void markDegenerateEdges(const Triangulation2d& tri);

  std::vector<Mat2> s_, inv_;
  std::vector<double> grad_, angle_;
  std::vector<int> ideal_;
  std::vector<std::uint8_t> flags_;
  const face::SurfaceLift* lift_ = nullptr;
};

/// S = (MᵀM)^{1/2} in closed form, (T + √det T · I) / √(tr T + 2√det T); false when M is
/// not finite or singular.
bool symmetricTransform(const Mat2& m, Mat2& s);

/// The neighbours of v counter-clockwise, when v's star is closed: the star triangles are
/// (v, ring[j], ring[j+1 mod n]). False when v is in no triangle, its star reaches the
/// border of the triangulation, or it has more than maxDegree neighbours.
bool gatherRing(const Triangulation2d& tri, VertexId v, std::vector<VertexId>& ring,
                std::size_t maxDegree = 4096);
/// The same, and the star triangles: tris[j] = (v, ring[j], ring[j+1 mod n]).
bool gatherRing(const Triangulation2d& tri, VertexId v, std::vector<VertexId>& ring, std::vector<TriId>& tris,
                std::size_t maxDegree = 4096);

/// Moves v to p. No check: the caller has verified that every triangle of the star stays
/// counter-clockwise. Triangulation2d has no coordinate setter, so this writes through the
/// reference returned by point(); the seeding quadtree keeps the old position (it only
/// seeds walks, which stay correct from any start).
void moveVertex(Triangulation2d& tri, VertexId v, const Vec2& p);

}  // namespace aniso::improve
