#pragma once
// BackgroundMesh2d — the metric field and the adaptive-control-space procedures of thesis
// sec. 3.4 on a planar Delaunay triangulation of control vertices (the engine of
// CSMesh2d; BackgroundMesh3d is the volume counterpart).
//
// Structure: a del2d::Triangulation2d built and updated by the meshing kernel itself, in
// the identity metric (sec. 3.4: "stored and managed in a way similar to the actual mesh
// being generated, using the same set of meshing procedures"), over the kernel's enlarged
// box of the bounds. Its vertices are the control vertices, the four box corners
// (vertices 0..3) included. Per vertex, beside the topology (STYLE.md 3): the sizing
// tensor M_s, its inverse (the length tensor interpolated by eq. 2.18), the cached
// parameterization tensor M_p (identity until adaptAux) and a "known" flag.
//
// Field (sec. 3.4.5): at a point Q (clamped into the bounds) the containing triangle is
// found by a visibility walk — from the caller's last located triangle when Q lies within
// two of its edge lengths, else from a triangle of the nearest vertex in the kernel's
// seeding quadtree (sec. 3.4.5: "an additional quadtree … for selection of good starting
// element"; leaves of 8 vertices here). When Q lies on an edge the triangle with the
// smaller slot is taken, so the field depends on Q only, never on the walk. The
// interpolation set A_s / A_t / A_o
// (BackgroundMeshOptions.h) is weighted by ω_i = d_R(Q, P_i)⁻² (eq. 3.2) with
// d_R(Q, P_i) = |M_p(P_i) (Q − P_i)|, the distance in S^R with the tensor cached at P_i
// (the parametric distance before adaptAux). Eq. 3.2 is applied to the length tensors,
// M_s(Q) = (Σ ω_i M_s(P_i)⁻¹ / Σ ω_i)⁻¹ — the n-point form of eq. 2.18 that the quadtree
// uses too (MetricBlend), so that both control spaces interpolate sizes, not inverse
// sizes. M_p(Q) = Σ ω_i M_p(P_i) / Σ ω_i (sec. 3.2.4 item 1: "interpolated using the same
// method"). ε_M shortcut: when d_M(Q, P_i) = |M_s(P_i) M_p(P_i) (Q − P_i)| < ε_M for a
// vertex of the set (the smallest such), its metric is returned as is; so every control
// vertex carries exactly its own metric.
//
// States: a new mesh carries no metric ("fresh"). Point sources inserted while fresh
// become control vertices with their metric at once (sec. 3.4.1 step 1; the proximity
// check merges a source into a vertex closer than ε_M by intersection); the box corners
// are then given metrics by extrapolation (initializeVertices). A continuous source on a
// fresh mesh starts from the regular grid of sec. 3.4.2. Once "valued", point sources use
// the updating procedure (sec. 3.4.1, "as in 3.3.1 with insertion replacing the split").
//
// Thread safety: the const methods may run concurrently on a mesh that is not being
// modified; point location keeps its state in a caller-owned MeshLocateHint2d (one per
// thread), never in the mesh. The kernel's own walk (PointLocation.h) draws its random
// choices from the triangulation's workspace and its seeding quadtree is filled lazily,
// so queries use a walk of their own on the caller's random state, and every modifying
// operation brings the seeding quadtree up to date before it returns.
#include <cstdint>
#include <functional>
#include <vector>

#include "mesher/control/BackgroundMeshGraph.h"
#include "mesher/control/BackgroundMeshOptions.h"
#include "mesher/control/ControlSpaceGrid.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/metric/Metric.h"

namespace aniso {

/// Caller-owned state of point location: the last located triangle (the next walk starts
/// there when the query is near it) and the random state of the walk. Any value is valid
/// for any mesh.
struct MeshLocateHint2d {
  std::uint32_t triangle = del2d::kNone;
  std::uint32_t rng = 0x9E3779B9u;
};

class BackgroundMesh2d {
 public:
  using MetricFn = std::function<Metric2d(const Vec2&)>;
  using MatFn = std::function<Mat2(const Vec2&)>;
  using VertexVisitor = std::function<void(const Vec2&, const Metric2d&)>;
  using VertexModifier = std::function<bool(const Vec2&, Metric2d&)>;
  /// Largest interpolation set gathered for A_o (triangles); beyond it the natural
  /// neighbourhood is truncated (never reached by a Delaunay mesh of sane points).
  static constexpr int kMaxNeighbourhood = 256;

  /// Throws InputError for an empty or non-finite box, ε_M < 0, ε_δ ≤ 0, l_Mmax ≤ 0 or bad
  /// options.
  BackgroundMesh2d(const Box2& bounds, const SizingParameters& params, const BackgroundMeshOptions& options);

  const Box2& bounds() const { return bounds_; }
  const del2d::Triangulation2d& triangulation() const { return tri_; }
  const BackgroundMeshOptions& options() const { return options_; }
  bool valued() const { return valued_; }
  bool hasAux() const { return hasAux_; }
  std::size_t pendingSources() const { return pending_; }
  /// Changes on every modification (for query caches).
  std::uint64_t revision() const { return revision_; }
  int vertexCount() const { return static_cast<int>(metric_.size()); }
  const Vec2& point(int v) const { return tri_.point(del2d::VertexId(v)); }
  const Metric2d& vertexMetric(int v) const { return metric_[v]; }
  const Mat2& vertexAux(int v) const { return aux_[v]; }
  /// The unique edges of the live triangles.
  VertexGraph graph() const;

  // ---- queries (const, thread-safe with one hint per thread) ----
  /// M_s and M_p at x (clamped into the bounds). Throws MeshingError while fresh.
  void sample(const Vec2& x, MeshLocateHint2d& hint, Metric2d& metric, Mat2& aux) const;
  /// The cached M_p at x (identity before adaptAux; works while fresh too).
  Mat2 auxAt(const Vec2& x, MeshLocateHint2d& hint) const;
  /// The live triangle whose closure contains x clamped into the bounds (on an edge: the
  /// one with the smaller slot, so that the field does not depend on the hint).
  del2d::TriId locate(const Vec2& x, MeshLocateHint2d& hint) const;
  /// The interpolation set of `method` at x (clamped) as vertex ids; returns the count.
  int interpolationSet(const Vec2& x, MeshLocateHint2d& hint, BackgroundInterpolation method,
                       std::vector<int>& out) const;
  /// Switches the interpolation method (the field changes; revision() too).
  void setInterpolation(BackgroundInterpolation method);

  // ---- operations (exclusive access) ----
  /// Point source (sec. 3.4.1): the initial procedure while fresh, the updating one when
  /// valued (see CSMesh2d.h for both). x is clamped into the bounds.
  void insertDiscrete(const Vec2& x, const Metric2d& m);
  /// Continuous source (sec. 3.4.2): fresh — the regular grid of points, every vertex
  /// gets the source's metric (a pending point source's vertex: intersected with it);
  /// valued — every vertex gets min_M(own, source). The source is evaluated at vertices
  /// clamped into the bounds (the box corners take the value of the nearest bounds
  /// point). Then every triangle whose interpolated metric differs by more than ε_δ from
  /// the target — the source when the mesh was fresh without point sources,
  /// min_M(field, source) otherwise — at its check point (the centroid; for a triangle
  /// reaching out of the bounds the bounds point nearest to it, when inside the
  /// triangle; with BackgroundCheck::CentroidEdges also its edge midpoints in the bounds,
  /// interpolated with the triangle's own set) gets a vertex at its circumcentre
  /// (clamped into the bounds; the check point when the clamped circumcentre is not
  /// strictly inside the circumcircle), repeatedly for the new triangles, down to
  /// BackgroundMeshOptions::minElementMetricLength and within maxVertices. With A_o,
  /// whose sets reach beyond the cavity, whole passes are repeated until one changes
  /// nothing (at most 16).
  void setContinuous(const MetricFn& source);
  /// Extrapolates metrics to the control vertices without one (the box corners, vertices
  /// of the parameterization adaptation) from the point-source vertices; the mesh is
  /// valued afterwards. No-op when valued; throws MeshingError when fresh without sources.
  void initializeVertices();
  /// Caches the exact M_p at every vertex and at every vertex created later; refines
  /// (as setContinuous) every triangle whose check point has δ(M_p exact, ·) > ε_δ
  /// against its interpolated value or any of its vertices' values (sec. 3.3.3 / 3.4.3),
  /// down to the resolution limit once valued. New vertices keep the field (interpolated
  /// metric; while fresh they get one from initializeVertices).
  void adaptAux(const MatFn& exact);
  /// Sec. 3.4.4 on every edge (BackgroundMeshGraph.h), d in S^R with M_p averaged over
  /// the edge's ends. Returns the number of rounds. Throws MeshingError while fresh.
  int smoothGradation(double gamma);
  void forEachVertex(const VertexVisitor& visit) const;
  void modifyVertices(const VertexModifier& modify);

  /// Points (u, v, 0), VTK_TRIANGLE cells (counter-clockwise), per-point tensors.
  ControlSpaceGrid grid() const;
  /// The kernel's invariants with the Delaunay property (identity), then: per-vertex
  /// arrays match the vertices, metrics SPD with consistent inverses, cached M_p SPD,
  /// every vertex known when valued, the pending count. Throws MeshingError naming the
  /// first violation.
  void validate() const;

 private:
  struct Inserted {
    int vertex = -1;      ///< new or coinciding vertex; −1 when refused
    bool created = false;
  };
  /// Refinement rule of the adaptations: whether triangle t (check point c, see
  /// checkPoint) must be refined; the values of a vertex inserted at p (returns whether the metric is
  /// known).
  using NeedsRefinement = std::function<bool(del2d::TriId t, const Vec2& c)>;
  using NewVertexValues = std::function<bool(const Vec2& p, del2d::TriId near, Metric2d& m, Mat2& aux)>;

  Vec2 clamp(const Vec2& x) const { return x.cwiseMax(bounds_.lo).cwiseMin(bounds_.hi); }
  /// Walk to a triangle whose closure contains p; `zeros` gets bit i when p is on the
  /// line of edge i.
  del2d::TriId walk(const Vec2& p, del2d::TriId start, std::uint32_t& rng, unsigned& zeros) const;
  /// The containing triangle, the one with the smaller slot when p is on an edge.
  del2d::TriId locateFrom(const Vec2& p, del2d::TriId start, std::uint32_t& rng) const;
  int gather(const Vec2& p, del2d::TriId t, BackgroundInterpolation method, std::uint32_t* out) const;
  int shortcutOrWeights(const Vec2& p, const std::uint32_t* set, int n, bool useMetric, double* w) const;
  Metric2d blendMetric(const Vec2& p, const std::uint32_t* set, int n) const;
  Mat2 blendAux(const Vec2& p, const std::uint32_t* set, int n) const;
  /// Field value at p located from `near` (a nearby live triangle).
  void fieldNear(const Vec2& p, del2d::TriId near, Metric2d* m, Mat2* aux) const;
  [[noreturn]] void failFresh(const Vec2& x) const;

  /// Candidates of the ε_M proximity check of a point in t: the vertices of t and of the
  /// triangles sharing an edge with it (at most 6) — they include every vertex closer to
  /// the point than the distance from that vertex to the boundary of its star.
  int nearVertices(del2d::TriId t, std::uint32_t* out) const;
  Inserted insertVertex(const Vec2& p, const Metric2d& m, const Mat2& aux, bool known, del2d::TriId near);
  void appendStar(int v, std::vector<del2d::TriId>& out) const;
  void neighbours(int v, std::vector<int>& out) const;
  double maxEdgeMetricLength(del2d::TriId t, const Mat2& transformation) const;
  bool belowResolution(del2d::TriId t, const Metric2d& m, const Mat2& aux) const;
  /// The point where the adaptations check triangle t: its centroid when in the bounds,
  /// else the nearest bounds point if it lies in t; false when there is none.
  bool checkPoint(del2d::TriId t, Vec2& x) const;
  /// The circumcentre of t clamped into the bounds when it is strictly inside the
  /// circumcircle, else the check point x.
  Vec2 refinementPoint(del2d::TriId t, const Vec2& x) const;
  void refine(const NeedsRefinement& needs, const NewVertexValues& values);
  void insertInitial(const Vec2& x, const Metric2d& m);
  void insertUpdate(const Vec2& x, const Metric2d& m);
  void addRing(int q, const Vec2& x, const Metric2d& before, const Mat2& transformation);
  void setVertex(int v, const Metric2d& m);
  void intersectVertex(int v, const Metric2d& m);
  void addInitialGrid();
  /// Ends every modifying operation, also when it throws: the seeding quadtree is up to
  /// date (so that concurrent queries only read it) and the revision is bumped.
  struct Modification {
    BackgroundMesh2d& mesh;
    ~Modification() {
      mesh.tri_.seeds();
      ++mesh.revision_;
    }
  };

  Box2 bounds_;
  double epsM_, epsDelta_, lMax_;
  BackgroundMeshOptions options_;
  del2d::Triangulation2d tri_;
  bool valued_ = false, hasAux_ = false;
  std::size_t pending_ = 0;
  std::uint64_t revision_ = 0;
  std::vector<Metric2d> metric_;     ///< M_s per vertex
  std::vector<Mat2> length_;         ///< M_s⁻¹ per vertex
  std::vector<Mat2> aux_;            ///< M_p per vertex (identity before adaptAux)
  std::vector<std::uint8_t> known_;  ///< vertex carries a metric
  MatFn auxExact_;
};

}  // namespace aniso
