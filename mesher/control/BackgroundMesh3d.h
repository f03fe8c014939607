#pragma once
// BackgroundMesh3d — the metric field and the adaptive-control-space procedures of thesis
// sec. 3.4 on a Delaunay tetrahedralization of control vertices (the engine of CSMesh3d;
// the volume counterpart of BackgroundMesh2d, whose header describes the design in
// full — only the differences are listed here).
//
// Structure: a del3d::TetMesh built by the kernel's Inserter (Bowyer–Watson, identity
// metric) inside createEnclosingBox of the bounds; its 8 corners (vertices 0..7) are
// control vertices too. Walks start at the last located tetrahedron when the query is
// near it, else at a tetrahedron of the nearest vertex found in a VertexSeedOctree
// (BackgroundMeshSeeds.h), updated with every insertion.
// Continuous sources start from the regular grid with its interior coordinates shifted
// by up to a tenth of a step (deterministically): an exact grid is cospherical
// everywhere, which makes the kernel's insertion several times slower.
// Field: interpolation sets A_s / A_t / A_o over tetrahedra (A_o: every tetrahedron whose
// circumsphere strictly contains the point), weights ω_i = |Q − P_i|⁻² in space (eq. 3.2),
// length tensors averaged (eq. 2.18 n-point form), ε_M shortcut with
// d_M(Q, P_i) = |M_s(P_i) (Q − P_i)|. No parameterization.
// Location: del3d::locate (visibility walk, random state owned by the caller — the
// MeshLocateHint3d — so queries are thread-safe).
// Thread safety as BackgroundMesh2d.
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "mesher/control/BackgroundMeshGraph.h"
#include "mesher/control/BackgroundMeshOptions.h"
#include "mesher/control/BackgroundMeshSeeds.h"
#include "mesher/control/ControlSpaceGrid.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/delaunay3d/Inserter.h"
#include "mesher/delaunay3d/TetMesh.h"
#include "mesher/metric/Metric.h"

namespace aniso {

/// Caller-owned state of point location (see MeshLocateHint2d).
struct MeshLocateHint3d {
  std::uint32_t tet = del3d::kNone;
  std::uint32_t rng = 0x9E3779B9u;
};

class BackgroundMesh3d {
 public:
  using MetricFn = std::function<Metric3d(const Vec3&)>;
  using VertexVisitor = std::function<void(const Vec3&, const Metric3d&)>;
  using VertexModifier = std::function<bool(const Vec3&, Metric3d&)>;
  /// Largest interpolation set gathered for A_o (tetrahedra); beyond it the natural
  /// neighbourhood is truncated.
  static constexpr int kMaxNeighbourhood = 512;

  /// Throws InputError for an empty or non-finite box or bad parameters / options.
  BackgroundMesh3d(const Box3& bounds, const SizingParameters& params, const BackgroundMeshOptions& options);

  const Box3& bounds() const { return bounds_; }
  const del3d::TetMesh& tetMesh() const { return *mesh_; }
  const BackgroundMeshOptions& options() const { return options_; }
  bool valued() const { return valued_; }
  std::size_t pendingSources() const { return pending_; }
  std::uint64_t revision() const { return revision_; }
  int vertexCount() const { return static_cast<int>(metric_.size()); }
  Vec3 point(int v) const { return mesh_->point(del3d::VertexId(static_cast<std::uint32_t>(v))); }
  const Metric3d& vertexMetric(int v) const { return metric_[v]; }
  /// The unique edges of the live tetrahedra.
  VertexGraph graph() const;

  // ---- queries (const, thread-safe with one hint per thread) ----
  /// M_s at x (clamped into the bounds). Throws MeshingError while fresh.
  Metric3d metricAt(const Vec3& x, MeshLocateHint3d& hint) const;
  /// The live tetrahedron whose closure contains x clamped into the bounds (on a face or
  /// an edge: the one with the smallest slot, so that the field does not depend on the
  /// hint).
  del3d::TetId locate(const Vec3& x, MeshLocateHint3d& hint) const;
  int interpolationSet(const Vec3& x, MeshLocateHint3d& hint, BackgroundInterpolation method,
                       std::vector<int>& out) const;
  void setInterpolation(BackgroundInterpolation method);

  // ---- operations (exclusive access); as BackgroundMesh2d ----
  void insertDiscrete(const Vec3& x, const Metric3d& m);
  void setContinuous(const MetricFn& source);
  void initializeVertices();
  int smoothGradation(double gamma);
  void forEachVertex(const VertexVisitor& visit) const;
  void modifyVertices(const VertexModifier& modify);

  /// Points, VTK_TETRA cells (positively oriented: (0,1,2) counter-clockwise seen from 3),
  /// per-point tensors.
  ControlSpaceGrid grid() const;
  /// The kernel's invariants (orientation, adjacency, Delaunay for the identity), then the
  /// per-vertex checks of BackgroundMesh2d::validate. Throws MeshingError.
  void validate() const;

 private:
  struct Inserted {
    int vertex = -1;
    bool created = false;
  };
  using NeedsRefinement = std::function<bool(del3d::TetId t, const Vec3& c)>;
  using NewVertexValues = std::function<void(const Vec3& p, del3d::TetId near, Metric3d& m)>;

  Vec3 clamp(const Vec3& x) const { return x.cwiseMax(bounds_.lo).cwiseMin(bounds_.hi); }
  del3d::TetId locateFrom(const Vec3& p, del3d::TetId start, std::uint32_t& rng) const;
  int gather(const Vec3& p, del3d::TetId t, BackgroundInterpolation method, std::uint32_t* out) const;
  Metric3d blendMetric(const Vec3& p, const std::uint32_t* set, int n) const;
  Metric3d fieldNear(const Vec3& p, del3d::TetId near) const;
  [[noreturn]] void failFresh(const Vec3& x) const;

  /// Candidates of the ε_M proximity check (see BackgroundMesh2d): the vertices of t and
  /// of the tetrahedra sharing a face with it (at most 8).
  int nearVertices(del3d::TetId t, std::uint32_t* out) const;
  Inserted insertVertex(const Vec3& p, const Metric3d& m, bool known, del3d::TetId near);
  void appendStar(int v, std::vector<del3d::TetId>& out) const;
  void neighbours(int v, std::vector<int>& out) const;
  Vec3 centroid(del3d::TetId t) const;
  double maxEdgeMetricLength(del3d::TetId t, const Mat3& m) const;
  bool belowResolution(del3d::TetId t, const Metric3d& m) const;
  bool checkPoint(del3d::TetId t, Vec3& x) const;
  Vec3 refinementPoint(del3d::TetId t, const Vec3& x) const;
  void refine(const NeedsRefinement& needs, const NewVertexValues& values);
  void insertInitial(const Vec3& x, const Metric3d& m);
  void insertUpdate(const Vec3& x, const Metric3d& m);
  void addRing(int q, const Vec3& x, const Metric3d& before, const Mat3& m);
  void setVertex(int v, const Metric3d& m);
  void intersectVertex(int v, const Metric3d& m);
  void addInitialGrid();
  /// Ends every modifying operation, also when it throws: the revision is bumped.
  struct Modification {
    BackgroundMesh3d& mesh;
    ~Modification() { ++mesh.revision_; }
  };

  Box3 bounds_;
  double epsM_, epsDelta_, lMax_;
  BackgroundMeshOptions options_;
  std::unique_ptr<del3d::TetMesh> mesh_;  ///< heap: the Inserter keeps a reference
  std::unique_ptr<del3d::Inserter> inserter_;
  std::unique_ptr<VertexSeedOctree> seeds_;
  bool valued_ = false;
  std::size_t pending_ = 0;
  std::uint64_t revision_ = 0;
  std::vector<Metric3d> metric_;     ///< M_s per vertex
  std::vector<Mat3> length_;         ///< M_s⁻¹ per vertex
  std::vector<std::uint8_t> known_;  ///< vertex carries a metric
};

}  // namespace aniso
