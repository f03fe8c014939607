#pragma once
// Removal of free vertices by quality (sec. 5.6 improvement, with the topological step the
// thesis' smoothing and flipping lack): the refinement places its points for the size the
// control space asks for, and where a solid is only one or two elements across (a box
// meshed at h close to its width, a thin wall) those points can be crowded, and no
// relocation or flip of the tets around them reaches the quality the boundary alone allows
// (docs/measurements.md).
//
// tryRemove(v): the star of v (the tets around it) is a polyhedron bounded by its link (the
// faces opposite v). It is re-tetrahedralised without v in two ways, and the better one
// (largest worst η_M) is taken when it beats the star's worst η_M by `gain`:
//   - edge collapse onto each link vertex w: the tets of the star without w, with v
//     replaced by w (a fan from w over the link faces not containing w);
//   - the Delaunay triangulation of the link vertices (del3d::buildDelaunay with v's
//     tensor as the in-sphere transform), when it contains every link face: the tets
//     inside the link, found by a flood from the link faces that does not cross them.
// Before v alone, v with its free neighbours (at most maxGroup of them) is tried as a group:
// their stars' union re-tetrahedralised by the Delaunay fill of its boundary vertices — one
// at a time, crowded points may each fail (the mean drops on the way, or the last one's link
// is cospherical and its fill misses link faces).
// Neither may lower the mesh's mean η_M: Σ new − Σ old ≥ mean · (new count − old count),
// the mean taken at run()'s start (without it a removal that raised a star's worst lowered
// a box's mean ratio by a tenth: docs/measurements.md).
// The retriangulation must also keep the star's worst guarded score (the smallest of η_M,
// the Euclidean η and the cubed dihedral sine, VertexMetrics::setGuardEuclidean): a better
// worst η_M bought with a smaller dihedral angle is refused (at the needle boundary
// triangles of short edges, η_M alone let the smallest dihedral angle fall below what the
// sliver removal could repair: docs/measurements.md).
// Check, then change: every new tet positively oriented (the exact orient3d, or a
// Euclidean score that certifies it, VertexMetrics::certifiesOrientation); the new tets'
// boundary is exactly the link (volume::replaceRegion refuses otherwise); every new edge
// (an edge of a new tet that is not an edge of the link) not longer than maxNewEdge in the
// metric (mean of its ends' transformation tensors), unless both its ends are fixed — the
// refinement's edge check exempts such edges too (VolumeRefinement.h) —, so the removal
// trades crowding for shape and does not coarsen the mesh beyond what the refinement
// accepts. Fixed vertices (node ≥ 0) are never removed, constrained faces (all on the
// link or beyond) are kept, so validateSolidTetMesh holds afterwards. A removed vertex is
// left in no tet (the extraction skips it).
// Candidates (tryRemove refuses others): the star's worst η_M below candidateBelow, and the
// star held by the boundary — at least heldShare of its tet-vertex incidences (v's
// excepted) are fixed vertices. Crowding among free vertices is the smoothing's to undo
// (they move); where the star hangs on the surface nodes they cannot, and that is where the
// refinement crowds points (a layer one or two elements thick). The rule is also what keeps
// the cost down: it leaves a small share of the poor stars (docs/measurements.md).
// run(): the candidates from one scan of the tets, worst first (ties by vertex id:
// deterministic); then rounds over the free vertices of the tets the previous round made,
// by id, until a round removes nothing (at most maxRounds). What it gains:
// docs/measurements.md.
// With a score cache (TetScores) the stars' scores are read from it and the created tets
// are measured into it (its contract).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"
#include "mesher/volume/SolidTetMesh.h"
#include "mesher/volume/improve/TetScores.h"
#include "mesher/volume/improve/VertexMetrics.h"

namespace aniso::improve3d {

struct VertexRemovalOptions {
  /// Candidates: free vertices whose star's worst η_M is below this.
  double candidateBelow = 0.8;
  /// run(): candidates only where the star is held by the boundary: at least this share of
  /// the star's tet-vertex incidences (v's excepted) are fixed vertices.
  double heldShare = 0.5;
  double gain = 1e-3;        ///< required increase of the star's worst η_M
  double maxNewEdge = 1.5;   ///< metric length bound of a new edge (the refinement's l_M)
  std::size_t maxStar = 96;  ///< larger stars are left alone
  std::size_t maxGroup = 4;        ///< the group: at most this many free neighbours with v
  std::size_t maxGroupTets = 128;  ///< and at most this many tets in their stars
  int maxRounds = 4;
  /// run()'s budget of Delaunay fills (single and group): max(minFills, tets / tetsPerFill),
  /// spent worst star first. A fill is dear (the kernel's set-up dominates for a few tens of
  /// points); where nearly every star is held by the boundary and poor (a thin plate) an
  /// unbounded run costs many times the rest of the improvement, while a usual mesh stays
  /// well within the budget (docs/measurements.md).
  std::size_t minFills = 256;
  std::size_t tetsPerFill = 200;
  /// and of candidates (docs/measurements.md): max(minCandidates, tets / tetsPerCandidate).
  std::size_t minCandidates = 1024;
  std::size_t tetsPerCandidate = 50;
};

struct VertexRemovalStats {
  std::size_t candidates = 0;  ///< tryRemove calls
  std::size_t removed = 0;  ///< vertices removed
  std::size_t byCollapse = 0, byDelaunay = 0, byGroup = 0;  ///< removals (a group counts once)
};

class VertexRemoval {
 public:
  VertexRemoval(SolidTetMesh& s, VertexMetrics& vm, TetScores* scores = nullptr) : s_(s), vm_(vm), scores_(scores) {}

  /// Removes the free vertex v when a retriangulation of its star beats the star's worst
  /// η_M by o.gain (see above); appends the new tets to `created`.
  bool tryRemove(del3d::VertexId v, const VertexRemovalOptions& o, std::vector<del3d::TetId>& created);
  /// The rounds of run() (see above); the created tets that are still alive at the end are
  /// left in `created` (for flips).
  VertexRemovalStats run(const VertexRemovalOptions& o, std::vector<del3d::TetId>& created);

 private:
  using Quad = std::array<del3d::VertexId, 4>;
  /// A face of the region's boundary: face `slot` (opposite tet[slot]) of the region's tet.
  struct LinkFace {
    Quad tet;
    int slot;
  };
  double score(del3d::TetId t) const { return scores_ ? (*scores_)[t] : vm_.score(t); }
  /// The region: the union of the stars of `remove` (false when a star is empty, the union
  /// has more than maxTets tets, or a vertex of `remove` is on its boundary), its boundary
  /// faces, vertices and edges.
  bool loadRegion(std::span<const del3d::VertexId> remove, std::size_t maxTets);
  /// The best retriangulation of the region into best_ (collapses onto each link vertex
  /// when `collapses`, the Delaunay fill with v's tensor), true when it passes every
  /// acceptance test.
  bool retriangulate(del3d::VertexId v, const VertexRemovalOptions& o, bool collapses);
  /// Replaces the region by best_ (false when replaceRegion refuses).
  bool commit(std::vector<del3d::TetId>& created);
  /// Worst score of `tets` (all positive), or a value ≤ floor as soon as one is at or below
  /// floor (or not positively oriented).
  double worstAbove(const std::vector<Quad>& tets, double floor) const;
  bool edgesShortEnough(const std::vector<Quad>& tets, double maxLength) const;
  /// best_ does not lower the region's worst guarded score (VertexMetrics::setGuardEuclidean).
  bool guardKept();
  /// best_ does not lower the mesh's mean η_M (meanEta_ the mean at run()'s start).
  bool meanKept() const;
  /// The Delaunay triangulation of the link vertices (v's tensor as the in-sphere
  /// transform), restricted to the region (false when it does not contain every link face).
  bool delaunayFill(del3d::VertexId v, std::vector<Quad>& out);

  SolidTetMesh& s_;
  VertexMetrics& vm_;
  TetScores* scores_;
  std::vector<del3d::TetId> star_, scratchStar_;  ///< the region's tets; one star
  std::vector<LinkFace> linkFaces_;
  std::vector<del3d::VertexId> link_;  ///< the link vertices, in discovery order
  std::vector<std::uint64_t> linkEdges_;  ///< sorted keys (lo << 32 | hi)
  std::vector<Quad> trial_, best_;
  del3d::TetMesh scratch_;
  std::vector<Vec3> points_;
  bool lastByCollapse_ = false, lastCluster_ = false;
  std::size_t removedNow_ = 0;  ///< vertices the last successful tryRemove removed
  std::size_t fills_ = 0, maxFills_ = static_cast<std::size_t>(-1);  ///< Delaunay fills made / allowed
  double meanEta_ = -1;  ///< the mesh's mean η_M (refreshMean: at run()'s start, or first use)
  void refreshMean();  ///< how the last tryRemove that succeeded retriangulated
};

}  // namespace aniso::improve3d
