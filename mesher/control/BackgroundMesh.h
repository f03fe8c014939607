#pragma once
// BackgroundMesh<D> — the metric field and the adaptive-control-space procedures of thesis
// sec. 3.4 on a Delaunay triangulation (D = 2, planar: the engine of CSMesh2d) or
// tetrahedralization (D = 3: the engine of CSMesh3d) of control vertices.
// BackgroundMesh2d / BackgroundMesh3d name the two instances.
//
// Structure: a Delaunay mesh built and updated by the meshing kernel itself, in the
// identity metric (sec. 3.4: "stored and managed in a way similar to the actual mesh
// being generated, using the same set of meshing procedures"), over the kernel's enlarged
// box of the bounds (BackgroundMeshKernel2d.h / 3d.h: the element type, point location,
// insertion and element geometry per dimension). Its vertices are the control vertices,
// the box corners (vertices 0..3 / 0..7) included. Per vertex, beside the topology
// (STYLE.md 3): the sizing tensor M_s, its inverse (the length tensor interpolated by
// eq. 2.18), a "known" flag and, in 2D only, the cached parameterization tensor M_p
// (identity until adaptAux). In 3D there is no parameterization: every "M_p" below is
// the identity, S^R is physical space.
//
// Field (sec. 3.4.5): at a point Q (clamped into the bounds) the containing element is
// found by a visibility walk — from the caller's last located element when Q lies within
// two of its edge lengths, else from an element of the nearest vertex in the kernel's
// seeding tree (sec. 3.4.5: "an additional quadtree … for selection of good starting
// element"). When Q lies on a face or an edge the element with the smallest slot is
// taken, so the field depends on Q only, never on the walk. The interpolation set
// A_s / A_t / A_o (BackgroundMeshOptions.h; A_o: every element whose circumsphere
// strictly contains Q) is weighted by ω_i = d_R(Q, P_i)⁻² (eq. 3.2) with
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
// fresh mesh starts from the regular grid of sec. 3.4.2 (in 3D with its interior
// coordinates shifted by up to a tenth of a step, deterministically: an exact grid is
// cospherical everywhere, which makes the kernel's insertion several times slower). Once
// "valued", point sources use the updating procedure (sec. 3.4.1, "as in 3.3.1 with
// insertion replacing the split").
//
// Thread safety: the const methods may run concurrently on a mesh that is not being
// modified; point location keeps its state in a caller-owned MeshLocateHint (one per
// thread), never in the mesh, and every modifying operation brings the kernel's search
// structures up to date before it returns.
#include <cstdint>
#include <functional>
#include <type_traits>
#include <vector>

#include "mesher/control/BackgroundMeshGraph.h"
#include "mesher/control/BackgroundMeshKernel2d.h"
#include "mesher/control/BackgroundMeshKernel3d.h"
#include "mesher/control/BackgroundMeshOptions.h"
#include "mesher/control/ControlSpaceGrid.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/metric/Metric.h"

namespace aniso {

/// Caller-owned state of point location: the last located element (the next walk starts
/// there when the query is near it) and the random state of the walk. Any value is valid
/// for any mesh.
template <int D>
struct MeshLocateHint {
  std::uint32_t element = 0xFFFFFFFFu;  ///< del2d::kNone / del3d::kNone: none yet
  std::uint32_t rng = 0x9E3779B9u;
};
using MeshLocateHint2d = MeshLocateHint<2>;
using MeshLocateHint3d = MeshLocateHint<3>;

/// The 3D stand-in for the parameterization tensor M_p: there is none (the identity).
struct NoParameterization {};

template <int D>
class BackgroundMesh {
  static_assert(D == 2 || D == 3, "BackgroundMesh<D> exists for D = 2 and D = 3");

 public:
  using Vec = Eigen::Matrix<double, D, 1>;
  using Mat = Eigen::Matrix<double, D, D>;
  using MetricD = Metric<D>;
  using Kernel = BackgroundMeshKernel<D>;
  using Elem = typename Kernel::Elem;
  /// M_p per vertex: a tensor in 2D, nothing in 3D.
  static constexpr bool kParameterized = D == 2;
  using Aux = std::conditional_t<kParameterized, Mat, NoParameterization>;
  using MetricFn = std::function<MetricD(const Vec&)>;
  using MatFn = std::function<Mat(const Vec&)>;
  using VertexVisitor = std::function<void(const Vec&, const MetricD&)>;
  using VertexModifier = std::function<bool(const Vec&, MetricD&)>;
  /// Largest interpolation set gathered for A_o (elements); beyond it the natural
  /// neighbourhood is truncated (never reached by a Delaunay mesh of sane points).
  static constexpr int kMaxNeighbourhood = D == 2 ? 256 : 512;

  /// Throws InputError for an empty or non-finite box, ε_M < 0, ε_δ ≤ 0, l_Mmax ≤ 0 or bad
  /// options.
  BackgroundMesh(const Box<D>& bounds, const SizingParameters& params, const BackgroundMeshOptions& options);

  const Box<D>& bounds() const { return bounds_; }
  const del2d::Triangulation2d& triangulation() const
    requires(D == 2)
  {
    return kernel_.triangulation();
  }
  const del3d::TetMesh& tetMesh() const
    requires(D == 3)
  {
    return kernel_.tetMesh();
  }
  const BackgroundMeshOptions& options() const { return options_; }
  bool valued() const { return valued_; }
  bool hasAux() const { return hasAux_; }
  std::size_t pendingSources() const { return pending_; }
  /// Changes on every modification (for query caches).
  std::uint64_t revision() const { return revision_; }
  int vertexCount() const { return static_cast<int>(metric_.size()); }
  decltype(auto) point(int v) const { return kernel_.point(static_cast<std::uint32_t>(v)); }
  const MetricD& vertexMetric(int v) const { return metric_[v]; }
  const Mat& vertexAux(int v) const
    requires(D == 2)
  {
    return aux_[v];
  }
  /// The unique edges of the live elements.
  VertexGraph graph() const;

  // ---- queries (const, thread-safe with one hint per thread) ----
  /// M_s and M_p at x (clamped into the bounds). Throws MeshingError while fresh.
  void sample(const Vec& x, MeshLocateHint<D>& hint, MetricD& metric, Mat& aux) const
    requires(D == 2);
  /// M_s at x (clamped into the bounds). Throws MeshingError while fresh.
  MetricD metricAt(const Vec& x, MeshLocateHint<D>& hint) const
    requires(D == 3);
  /// The cached M_p at x (identity before adaptAux; works while fresh too).
  Mat auxAt(const Vec& x, MeshLocateHint<D>& hint) const
    requires(D == 2);
  /// The live element whose closure contains x clamped into the bounds (on a face or an
  /// edge: the one with the smallest slot, so that the field does not depend on the hint).
  Elem locate(const Vec& x, MeshLocateHint<D>& hint) const;
  /// The interpolation set of `method` at x (clamped) as vertex ids; returns the count.
  int interpolationSet(const Vec& x, MeshLocateHint<D>& hint, BackgroundInterpolation method,
                       std::vector<int>& out) const;
  /// Switches the interpolation method (the field changes; revision() too).
  void setInterpolation(BackgroundInterpolation method);

  // ---- operations (exclusive access) ----
  /// Point source (sec. 3.4.1): the initial procedure while fresh, the updating one when
  /// valued (see CSMesh2d.h for both). x is clamped into the bounds.
  void insertDiscrete(const Vec& x, const MetricD& m);
  /// Continuous source (sec. 3.4.2): fresh — the regular grid of points, every vertex
  /// gets the source's metric (a pending point source's vertex: intersected with it);
  /// valued — every vertex gets min_M(own, source). The source is evaluated at vertices
  /// clamped into the bounds (the box corners take the value of the nearest bounds
  /// point). Then every element whose interpolated metric differs by more than ε_δ from
  /// the target — the source when the mesh was fresh without point sources,
  /// min_M(field, source) otherwise — at its check point (the centroid; for an element
  /// reaching out of the bounds the bounds point nearest to it, when inside the
  /// element; with BackgroundCheck::CentroidEdges also its edge midpoints in the bounds,
  /// interpolated with the element's own set) gets a vertex at its circumcentre
  /// (clamped into the bounds; the check point when the clamped circumcentre is not
  /// strictly inside the circumsphere), repeatedly for the new elements, down to
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
  void adaptAux(const MatFn& exact)
    requires(D == 2);
  /// Sec. 3.4.4 on every edge (BackgroundMeshGraph.h), d in S^R with M_p averaged over
  /// the edge's ends. Returns the number of rounds. Throws MeshingError while fresh.
  int smoothGradation(double gamma);
  void forEachVertex(const VertexVisitor& visit) const;
  void modifyVertices(const VertexModifier& modify);

  /// Points (in 2D (u, v, 0)), VTK_TRIANGLE (counter-clockwise) / VTK_TETRA (positively
  /// oriented: (0,1,2) counter-clockwise seen from 3) cells, per-point tensors.
  ControlSpaceGrid grid() const;
  /// The kernel's invariants with the Delaunay property (identity), then: per-vertex
  /// arrays match the vertices, metrics SPD with consistent inverses, cached M_p SPD,
  /// every vertex known when valued, the pending count. Throws MeshingError naming the
  /// first violation.
  void validate() const;

 private:
  /// Refinement rule of the adaptations: whether element t (check point c, see
  /// checkPoint) must be refined; the values of a vertex inserted at p (returns whether
  /// the metric is known).
  using NeedsRefinement = std::function<bool(Elem t, const Vec& c)>;
  using NewVertexValues = std::function<bool(const Vec& p, Elem near, MetricD& m, Aux& aux)>;
  /// A set buffer: an A_o set plus room for one more element's vertices.
  static constexpr int kSetBuffer = kMaxNeighbourhood + D;

  Vec clamp(const Vec& x) const { return x.cwiseMax(bounds_.lo).cwiseMin(bounds_.hi); }
  /// M_p(P_v) d: the vector d from vertex v in S^R.
  Vec inR(std::uint32_t v, const Vec& d) const {
    if constexpr (kParameterized)
      return aux_[v] * d;
    else
      return d;
  }
  /// M_p before adaptAux.
  static Aux identityAux() {
    if constexpr (kParameterized)
      return Mat::Identity();
    else
      return {};
  }
  /// The transformation M_s M_p of a point (its sizing metric and M_p).
  static Mat transformation(const MetricD& m, const Aux& aux) {
    if constexpr (kParameterized)
      return m.matrix() * aux;
    else
      return m.matrix();
  }
  /// The containing element from `start` (any: invalid or dead starts at the seeding
  /// tree); throws MeshingError when location fails.
  Elem locateFrom(const Vec& p, Elem start, std::uint32_t& rng) const;
  int gather(const Vec& p, Elem t, BackgroundInterpolation method, std::uint32_t* out) const;
  /// The index in `set` of the ε_M shortcut (with useMetric) or of a vertex at p, or −1
  /// with the weights ω_i of eq. 3.2 in w.
  int shortcutOrWeights(const Vec& p, const std::uint32_t* set, int n, bool useMetric, double* w) const;
  MetricD blendMetric(const Vec& p, const std::uint32_t* set, int n) const;
  Aux blendAux(const Vec& p, const std::uint32_t* set, int n) const;
  /// Field value at p located from `near` (a nearby live element).
  void fieldNear(const Vec& p, Elem near, MetricD* m, Aux* aux) const;
  [[noreturn]] void failFresh(const Vec& x) const;

  /// Candidates of the ε_M proximity check of a point in t: the vertices of t and of the
  /// elements sharing a side with it (at most 6 / 8) — they include every vertex closer
  /// to the point than the distance from that vertex to the boundary of its star.
  int nearVertices(Elem t, std::uint32_t* out) const;
  KernelInsertion insertVertex(const Vec& p, const MetricD& m, const Aux& aux, bool known, Elem near);
  void neighbours(int v, std::vector<int>& out) const;
  bool belowResolution(Elem t, const MetricD& m, const Aux& aux) const;
  /// The point where the adaptations check element t: its centroid when in the bounds,
  /// else the nearest bounds point if it lies in t; false when there is none.
  bool checkPoint(Elem t, Vec& x) const;
  /// The circumcentre of t clamped into the bounds when it is strictly inside the
  /// circumsphere, else the check point x.
  Vec refinementPoint(Elem t, const Vec& x) const;
  void refine(const NeedsRefinement& needs, const NewVertexValues& values);
  /// The ε_M proximity check of a point source at p with transformation tq: the nearest
  /// candidate of t closer than ε_M (with onlyKnown, among those carrying a metric), or −1.
  int closeVertex(const Vec& p, Elem t, const Mat& tq, bool onlyKnown) const;
  void insertInitial(const Vec& x, const MetricD& m);
  void insertUpdate(const Vec& x, const MetricD& m);
  void addRing(int q, const Vec& x, const MetricD& before, const Mat& transformation);
  void setVertex(int v, const MetricD& m);
  void intersectVertex(int v, const MetricD& m);
  void addInitialGrid();
  /// Ends every modifying operation, also when it throws: the kernel's search structures
  /// are up to date (so that concurrent queries only read them) and the revision is
  /// bumped.
  struct Modification {
    BackgroundMesh& mesh;
    ~Modification() {
      mesh.kernel_.settle();
      ++mesh.revision_;
    }
  };

  Box<D> bounds_;
  double epsM_, epsDelta_, lMax_;
  BackgroundMeshOptions options_;
  Kernel kernel_;
  bool valued_ = false, hasAux_ = false;
  std::size_t pending_ = 0;
  std::uint64_t revision_ = 0;
  std::vector<MetricD> metric_;      ///< M_s per vertex
  std::vector<Mat> length_;          ///< M_s⁻¹ per vertex
  std::vector<Aux> aux_;             ///< M_p per vertex (identity before adaptAux)
  std::vector<std::uint8_t> known_;  ///< vertex carries a metric
  std::function<Aux(const Vec&)> auxExact_;  ///< the exact M_p once adaptAux has run
};

using BackgroundMesh2d = BackgroundMesh<2>;
using BackgroundMesh3d = BackgroundMesh<3>;

}  // namespace aniso
