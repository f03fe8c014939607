#include "mesher/volume/BoundaryRecovery.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <unordered_map>
#include <unordered_set>

#include <Eigen/Geometry>

#include "mesher/core/Log.h"
#include "mesher/volume/BoundaryCrossing.h"
#include "mesher/volume/CavityRecovery.h"
#include "mesher/volume/MeshQueries.h"
#include "mesher/volume/Pipe.h"
#include "mesher/volume/RecoveryDiagnosis.h"

namespace aniso {

using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

void RecoveryStats::merge(const RecoveryStats& o) {
  edges += o.edges;
  faces += o.faces;
  missingEdges += o.missingEdges;
  missingFaces += o.missingFaces;
  for (int p = 0; p < kPhases; ++p) {
    edgesRecovered[p] += o.edgesRecovered[p];
    facesRecovered[p] += o.facesRecovered[p];
  }
  steinerPoints += o.steinerPoints;
  flips.flips23 += o.flips.flips23;
  flips.removals += o.flips.removals;
  flips.tried += o.flips.tried;
}

namespace {

/// Surface triangles flatter than this (area / longest edge²) are named in failures.
constexpr double kFlatShape = 0.01;

std::uint64_t edgeKey(VertexId a, VertexId b) {
  const std::uint64_t p = std::min(a.index, b.index), q = std::max(a.index, b.index);
  return (p << 32) | q;
}

class Recovery {
 public:
  Recovery(BoundaryTriangulation& bt, const RecoveryOptions& o) : bt_(bt), mesh_(bt.tets.mesh), opt_(o) {
    for (const auto& e : bt_.boundary.edges) boundaryEdges_.insert(edgeKey(e[0], e[1]));
    guard_ = [this](VertexId a, VertexId b) { return boundaryEdges_.count(edgeKey(a, b)) > 0; };
  }

  RecoveryResult run() {
    RecoveryResult r;
    RecoveryStats& s = r.stats;
    s.edges = static_cast<long long>(bt_.boundary.edges.size());
    s.faces = static_cast<long long>(bt_.boundary.triangles.size());
    collectMissing();
    s.missingEdges = static_cast<long long>(missingEdges_.size());
    s.missingFaces = static_cast<long long>(missingFaces_.size());
    r.selfCrossing = selfCrossings(r);
    if (r.selfCrossing && !opt_.pastSelfCrossings) return r;
    for (int phase = 0; phase < RecoveryStats::kPhases; ++phase) {
      if (phase == 1 && !opt_.interiorPoints) break;
      const std::size_t e0 = missingEdges_.size(), f0 = missingFaces_.size();
      std::size_t best = e0 + f0;
      int stalled = 0;
      for (int round = 0; round < opt_.maxRounds && !(missingEdges_.empty() && missingFaces_.empty()); ++round) {
        checkCancel(opt_.cancel, "boundary recovery");
        const std::size_t before = missingEdges_.size() + missingFaces_.size();
        const long long points = s.steinerPoints;
        if (phase == 1) cavityRound(s);
        pipeRound(s);
        collectMissing();
        // Progress: fewer missing entities, or new vicinity points to work with (for at
        // most maxStalledRounds rounds without a new best).
        const std::size_t now = missingEdges_.size() + missingFaces_.size();
        if (now >= before && s.steinerPoints == points) break;
        stalled = now < best ? 0 : stalled + 1;
        best = std::min(best, now);
        if (stalled >= opt_.maxStalledRounds) break;
      }
      s.edgesRecovered[phase] = static_cast<long long>(e0) - static_cast<long long>(missingEdges_.size());
      s.facesRecovered[phase] = static_cast<long long>(f0) - static_cast<long long>(missingFaces_.size());
    }
    logLeft();
    for (const int e : missingEdges_) {
      const auto& ed = bt_.boundary.edges[e];
      r.left.push_back({bt_.boundary.triangleFace[bt_.boundary.edgeTriangle[e]],
                        "boundary edge between surface nodes " + std::to_string(bt_.tets.node[ed[0].index]) + " and " +
                            std::to_string(bt_.tets.node[ed[1].index]) + " not recovered" +
                            shapeNote(bt_.boundary.triangles[bt_.boundary.edgeTriangle[e]]),
                        {bt_.tets.node[ed[0].index], bt_.tets.node[ed[1].index]}});
    }
    for (const int f : missingFaces_) {
      const auto& t = bt_.boundary.triangles[f];
      r.left.push_back({bt_.boundary.triangleFace[f], "boundary triangle (surface nodes " +
                                                          std::to_string(bt_.tets.node[t[0].index]) + ", " +
                                                          std::to_string(bt_.tets.node[t[1].index]) + ", " +
                                                          std::to_string(bt_.tets.node[t[2].index]) + ") not recovered" +
                                                          shapeNote(t),
                        {bt_.tets.node[t[0].index], bt_.tets.node[t[1].index], bt_.tets.node[t[2].index]}});
    }
    return r;
  }

 private:
  /// Fills r.left with the missing edges crossing a present boundary entity and the
  /// entities they cross (BoundaryCrossing.h); true when there is one.
  bool selfCrossings(RecoveryResult& r) {
    const auto nodes = [this](const std::vector<VertexId>& v) {
      std::string s;
      for (const VertexId x : v) s += (s.empty() ? "" : ", ") + std::to_string(bt_.tets.node[x.index]);
      return s;
    };
    for (const int e : missingEdges_) {
      const auto& ed = bt_.boundary.edges[e];
      const std::vector<VertexId> x = volume::boundaryCrossing(mesh_, ed[0], ed[1], guard_, pipe_);
      if (x.empty()) continue;
      const int face = bt_.boundary.triangleFace[bt_.boundary.edgeTriangle[e]];
      const std::string what = "the boundary mesh intersects itself: boundary edge (surface nodes " +
                               nodes({ed[0], ed[1]}) + ") crosses the boundary " +
                               (x.size() == 2 ? "edge" : "triangle") + " (" + nodes(x) + ")";
      // Both entities are named, so that splitting (a triangle by its longest edge) refines
      // both sides of the crossing: water_module's solid 3 converged in 8 rounds (196 ... 4
      // split); with every edge of a crossed triangle split it diverged (379 ... 650).
      r.left.push_back({face, what, {bt_.tets.node[ed[0].index], bt_.tets.node[ed[1].index]}});
      std::vector<int> crossed;
      for (const VertexId v : x) crossed.push_back(bt_.tets.node[v.index]);
      r.left.push_back({face, what, crossed});
    }
    return !r.left.empty();
  }

  /// The local configuration of every entity left missing (RecoveryDiagnosis.h), at debug level.
  void logLeft() const {
    const volume::IsBoundaryVertex fixed = [this](VertexId v) { return bt_.tets.isFixed(v); };
    const std::string solid = "solid " + std::to_string(bt_.tets.solid + 1) + ": missing ";
    for (const int e : missingEdges_)
      logDebug(solid + volume::describeMissingEdge(mesh_, bt_.boundary.edges[e][0], bt_.boundary.edges[e][1], fixed,
                                                   guard_));
    for (const int f : missingFaces_)
      logDebug(solid + volume::describeMissingTriangle(mesh_, bt_.boundary.triangles[f], fixed, guard_));
  }

  /// A note on a nearly flat surface triangle (area / longest edge² below kFlatShape,
  /// 0.43 for the equilateral one): such slivers of the surface mesh leave almost no room
  /// for a point inside the solid next to them.
  std::string shapeNote(const std::array<VertexId, 3>& t) const {
    const Vec3 a = mesh_.point(t[0]), b = mesh_.point(t[1]), c = mesh_.point(t[2]);
    const double l = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    const double shape = 0.5 * (b - a).cross(c - a).norm() / (l * l);
    if (!(shape < kFlatShape)) return "";
    char buf[96];
    std::snprintf(buf, sizeof buf, "; its surface triangle is nearly flat (area/length^2 %.2g)", shape);
    return buf;
  }

  /// Recomputes the missing lists and constrains every present boundary face. The first
  /// call checks every entity; later calls only the ones that can have changed: a present
  /// face is constrained, so no operator removes it (flips and cavities refuse to, the
  /// inserter never crosses it), and neither its edges; so only the missing faces, the
  /// missing edges and the edges of missing faces are looked at again.
  void collectMissing() {
    const SolidBoundary& b = bt_.boundary;
    std::vector<int> edges, faces;
    if (!checked_) {
      for (std::size_t e = 0; e < b.edges.size(); ++e) edgeIndex_[edgeKey(b.edges[e][0], b.edges[e][1])] = static_cast<int>(e);
      checked_ = true;
      collectAllMissing();
      return;
    } else {
      faces = missingFaces_;
      std::unordered_set<int> seen(missingEdges_.begin(), missingEdges_.end());
      edges = missingEdges_;
      for (const int f : missingFaces_)
        for (int k = 0; k < 3; ++k) {
          const int e = edgeIndex_.at(edgeKey(b.triangles[f][k], b.triangles[f][(k + 1) % 3]));
          if (seen.insert(e).second) edges.push_back(e);
        }
      std::sort(edges.begin(), edges.end());
    }
    missingEdges_.clear();
    missingFaces_.clear();
    for (const int e : edges)
      if (!volume::findEdge(mesh_, b.edges[e][0], b.edges[e][1], star_).valid()) missingEdges_.push_back(e);
    for (const int f : faces) {
      const auto& t = b.triangles[f];
      const volume::FaceHandle h = volume::findFace(mesh_, t[0], t[1], t[2], star_);
      if (!h.valid()) {
        missingFaces_.push_back(f);
        continue;
      }
      if (!mesh_.isConstrained(h.tet, h.face)) mesh_.setConstrained(h.tet, h.face, true);
    }
  }

  /// collectMissing's first pass over every edge and face: one vertex star per first
  /// vertex (an entity's first vertex: edges[e][0], triangles[f][0]), the entities around
  /// it looked up in it (the same handles as findEdge / findFace, about five times fewer
  /// star searches).
  void collectAllMissing() {
    const SolidBoundary& b = bt_.boundary;
    missingEdges_.clear();
    missingFaces_.clear();
    const std::size_t ne = b.edges.size(), nf = b.triangles.size();
    std::vector<std::uint32_t> firstVertex(ne + nf);
    for (std::size_t e = 0; e < ne; ++e) firstVertex[e] = b.edges[e][0].index;
    for (std::size_t f = 0; f < nf; ++f) firstVertex[ne + f] = b.triangles[f][0].index;
    std::vector<std::uint32_t> byVertex(ne + nf);  // entity ids (edges, then faces + ne) by first vertex
    for (std::size_t k = 0; k < byVertex.size(); ++k) byVertex[k] = static_cast<std::uint32_t>(k);
    std::stable_sort(byVertex.begin(), byVertex.end(),
                     [&](std::uint32_t x, std::uint32_t y) { return firstVertex[x] < firstVertex[y]; });
    std::vector<std::uint8_t> missing(ne + nf, 0);
    for (std::size_t k = 0; k < byVertex.size();) {
      const VertexId a(firstVertex[byVertex[k]]);
      volume::vertexStar(mesh_, a, star_);
      for (; k < byVertex.size() && firstVertex[byVertex[k]] == a.index; ++k) {
        const std::uint32_t id = byVertex[k];
        if (id < ne) {
          missing[id] = !volume::findEdgeInStar(mesh_, a, b.edges[id][1], star_).valid();
          continue;
        }
        const auto& t = b.triangles[id - ne];
        const volume::FaceHandle h = volume::findFaceInStar(mesh_, t[0], t[1], t[2], star_);
        missing[id] = !h.valid();
        if (h.valid() && !mesh_.isConstrained(h.tet, h.face)) mesh_.setConstrained(h.tet, h.face, true);
      }
    }
    for (std::size_t e = 0; e < ne; ++e)
      if (missing[e]) missingEdges_.push_back(static_cast<int>(e));
    for (std::size_t f = 0; f < nf; ++f)
      if (missing[ne + f]) missingFaces_.push_back(static_cast<int>(f));
  }

  bool edgesPresent(const std::array<VertexId, 3>& t) {
    for (int k = 0; k < 3; ++k)
      if (!volume::findEdge(mesh_, t[k], t[(k + 1) % 3], star_).valid()) return false;
    return true;
  }

  void pipeRound(RecoveryStats& s) {
    for (const int e : missingEdges_) {
      checkCancel(opt_.cancel, "boundary recovery");
      const auto& ed = bt_.boundary.edges[e];
      const auto measure = [&] { volume::segmentPipe(mesh_, ed[0], ed[1], pipe_); };
      if (sameAsFailure(failedEdges_, e, measure)) continue;
      if (!volume::reduceEdgePipe(mesh_, ed[0], ed[1], guard_, opt_.maxChangesPerEntity, s.flips))
        rememberFailure(failedEdges_, e, measure);
    }
    for (const int f : missingFaces_) {
      checkCancel(opt_.cancel, "boundary recovery");
      const auto& t = bt_.boundary.triangles[f];
      if (!edgesPresent(t)) continue;
      const auto measure = [&] { volume::trianglePipe(mesh_, t[0], t[1], t[2], pipe_); };
      if (sameAsFailure(failedFaces_, f, measure)) continue;
      if (volume::reduceFacePipe(mesh_, t[0], t[1], t[2], guard_, opt_.maxChangesPerEntity, s.flips)) {
        const volume::FaceHandle h = volume::findFace(mesh_, t[0], t[1], t[2], star_);
        if (h.valid()) mesh_.setConstrained(h.tet, h.face, true);
      } else {
        rememberFailure(failedFaces_, f, measure);
      }
    }
  }

  /// The entities crossing a missing entity (pipe_), by their vertices, sorted: equal
  /// lists mean the same local configuration for the flips.
  std::vector<std::uint64_t> pipeKeys() const {
    std::vector<std::uint64_t> k;
    k.reserve(2 * pipe_.faces.size() + pipe_.edges.size() + 1);
    for (const volume::FaceRef& f : pipe_.faces) {
      std::array<std::uint64_t, 3> v{};
      for (int m = 0; m < 3; ++m) v[m] = mesh_.vertex(f.tet, del3d::kFaceVertex[f.face][m]).index;
      std::sort(v.begin(), v.end());
      k.push_back(v[0] << 32 | v[1]);
      k.push_back(v[2] << 32 | 0xFFFFFFFFu);  // marks a face (no vertex index is 2^32 - 1)
    }
    for (const volume::EdgeRef& e : pipe_.edges) k.push_back(edgeKey(mesh_.vertex(e.tet, e.i), mesh_.vertex(e.tet, e.j)));
    k.push_back(pipe_.degenerate ? 1 : 0);
    std::sort(k.begin(), k.end());
    return k;
  }

  /// Pipe reduction failed on entity `id` before and its pipe (measured by `measure`) is
  /// the same as then: flips gave up on this configuration, trying again would too.
  template <class Measure>
  bool sameAsFailure(const std::unordered_map<int, std::vector<std::uint64_t>>& failed, int id,
                     const Measure& measure) {
    const auto it = failed.find(id);
    if (it == failed.end()) return false;
    measure();
    return it->second == pipeKeys();
  }

  template <class Measure>
  void rememberFailure(std::unordered_map<int, std::vector<std::uint64_t>>& failed, int id, const Measure& measure) {
    measure();
    failed[id] = pipeKeys();
  }

  void cavityRound(RecoveryStats& s) {
    if (!cavity_) cavity_ = std::make_unique<volume::CavityRecovery>(bt_);
    cavity_->newRound();
    for (const int f : missingFaces_) {
      checkCancel(opt_.cancel, "boundary recovery");
      s.steinerPoints += cavity_->recoverTriangle(f);
    }
    for (const int e : missingEdges_) {
      checkCancel(opt_.cancel, "boundary recovery");
      s.steinerPoints += cavity_->recoverEdge(e);
    }
  }

  BoundaryTriangulation& bt_;
  TetMesh& mesh_;
  const RecoveryOptions& opt_;
  std::unordered_set<std::uint64_t> boundaryEdges_;
  volume::EdgeGuard guard_;
  std::vector<int> missingEdges_, missingFaces_;
  std::vector<TetId> star_;
  volume::Pipe pipe_;                                            ///< scratch
  std::unordered_map<int, std::vector<std::uint64_t>> failedEdges_, failedFaces_;  ///< pipe at the last failure
  std::unique_ptr<volume::CavityRecovery> cavity_;  ///< kept across rounds (vicinity attempts)
  std::unordered_map<std::uint64_t, int> edgeIndex_;  ///< boundary edge by its vertex pair
  bool checked_ = false;                              ///< collectMissing ran once over everything
};

}  // namespace

RecoveryResult recoverBoundary(BoundaryTriangulation& bt, const RecoveryOptions& options) {
  return Recovery(bt, options).run();
}

}  // namespace aniso
