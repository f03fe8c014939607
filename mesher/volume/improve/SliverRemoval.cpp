#include "mesher/volume/improve/SliverRemoval.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <string>
#include <vector>

#include "mesher/core/Log.h"
#include "mesher/delaunay3d/Inserter.h"
#include "mesher/delaunay3d/Locate.h"
#include "mesher/volume/improve/PolyhedronReconnection.h"
#include "mesher/volume/improve/QualityEdgeRemoval.h"
#include "mesher/volume/improve/QualityFlips.h"
#include "mesher/volume/improve/SliverSteinerPoint.h"
#include "mesher/volume/improve/TetStar.h"
#include "mesher/volume/TetQuality.h"
#include "mesher/volume/improve/VertexMover.h"
#include "mesher/volume/refine/TetMetricGeometry.h"

namespace aniso::improve3d {
namespace {

using del3d::TetId;
using del3d::VertexId;

/// Relocation steps (VertexMover::relocate, each a local search) of a new Steiner point.
constexpr int kSteinerRelocations = 4;

class SliverRemover {
 public:
  SliverRemover(SolidTetMesh& s, const ControlSpace3d& cs, VertexMetrics& vm, double angle, double euclidean,
                bool insertion)
      : s_(s),
        cs_(cs),
        vm_(vm),
        angles_(angle, euclidean),
        insertion_(insertion),
        flips_(s, vm, 0.0),
        mover_(s, vm),
        inserter_(s.mesh, 0x51F3A7u) {}

  /// One round over `slivers` (those still slivers); returns the ones left.
  std::vector<TetId> round(const std::vector<TetId>& slivers);
  SliverStats stats;

 private:
  bool isSliver(TetId t) const { return s_.mesh.isAlive(t) && vm_.isSliver(t, angles_); }
  bool attack(TetId t);
  bool flipAway(TetId t);
  bool removeEdges(TetId t);
  bool reconnect(TetId t);
  void flipCreatedSlivers();
  void candidates(TetId t, std::vector<Vec3>& out) const;
  bool insertAt(TetId t, const Vec3& c);
  bool insertPoint(TetId t);
  bool steinerPoint(TetId t);

  SolidTetMesh& s_;
  const ControlSpace3d& cs_;
  VertexMetrics& vm_;
  VertexMetrics::SliverAngles angles_;
  bool insertion_;
  QualityFlips flips_;
  VertexMover mover_;
  del3d::Inserter inserter_;
  std::vector<TetId> created_, star_;
  std::uint32_t rng_ = 0x2F6B1Du;
};

// Flips of t, then of the created tets that are slivers, while they succeed.
bool SliverRemover::flipAway(TetId t) {
  created_.clear();
  const std::size_t before = flips_.counts().total();
  if (!flips_.visit(t, created_)) return false;
  for (std::size_t k = 0; k < created_.size() && k < 64; ++k)
    if (isSliver(created_[k])) flips_.visit(created_[k], created_);
  stats.flips += flips_.counts().total() - before;
  return true;
}

// Flips of the slivers among created_ (and of those the flips create, up to 64).
void SliverRemover::flipCreatedSlivers() {
  const std::size_t before = flips_.counts().total();
  for (std::size_t k = 0; k < created_.size() && k < 64; ++k)
    if (isSliver(created_[k])) flips_.visit(created_[k], created_);
  stats.flips += flips_.counts().total() - before;
}

// Removal of one of t's edges whose ring is too large for T32/T44, then flips of the created
// slivers.
bool SliverRemover::removeEdges(TetId t) {
  static constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  created_.clear();
  for (const auto& e : kEdge) {
    if (!removeEdgeByQuality(s_, vm_, t, e[0], e[1], created_)) continue;
    ++stats.edgeRemovals;
    flipCreatedSlivers();
    return true;
  }
  return false;
}

// The sliver and the tets around it tetrahedralized again (PolyhedronReconnection.h); while
// the new tets hold one still below kReconnectionAngleDeg, it in turn (at most
// kReconnectionChain times: the best tiling of a polyhedron may keep a flat tet that a
// neighbouring one removes); then flips of the created slivers.
bool SliverRemover::reconnect(TetId t) {
  if (!(tetMinDihedral(s_.mesh, t) < kReconnectionAngleDeg)) return false;
  created_.clear();
  if (!reconnectPolyhedron(s_, t, created_)) return false;
  ++stats.reconnections;
  for (int k = 1; k < kReconnectionChain; ++k) {
    TetId flattest;
    double angle = kReconnectionAngleDeg;
    for (const TetId u : created_) {
      if (!s_.mesh.isAlive(u)) continue;
      if (const double a = tetMinDihedral(s_.mesh, u); a < angle) angle = a, flattest = u;
    }
    if (!flattest.valid() || !reconnectPolyhedron(s_, flattest, created_)) break;
    ++stats.reconnections;
  }
  flipCreatedSlivers();
  return true;
}

// The candidate points of step 3: the metric circumcentre, then for each boundary face of
// the sliver the apex of the regular tet on it, inside (in the tet's metric): a sliver
// lying on a curved boundary (two boundary faces) has its circumcentre far away.
void SliverRemover::candidates(TetId t, std::vector<Vec3>& out) const {
  out.clear();
  const std::uint32_t* tv = s_.mesh.tetVertices(t);
  const Mat3 m = vm_.tetMetric(tv);
  Vec3 p[4];
  for (int i = 0; i < 4; ++i) p[i] = s_.mesh.point(VertexId(tv[i]));
  Vec3 c;
  if (refine3d::metricCircumcentre(m, p[0], p[1], p[2], p[3], c)) out.push_back(c);
  const Mat3 inv = m.inverse();
  for (int i = 0; i < 4; ++i) {
    if (s_.mesh.neighbour(t, i).valid() && !s_.mesh.isConstrained(t, i)) continue;  // hull and embedded faces
    const Vec3 a = m * p[del3d::kFaceVertex[i][0]], b = m * p[del3d::kFaceVertex[i][1]],
               d = m * p[del3d::kFaceVertex[i][2]];
    Vec3 n = (b - a).cross(d - a);
    if (n.dot(m * p[i] - a) < 0) n = -n;  // towards the inside (vertex i's side)
    const double len = ((b - a).norm() + (d - b).norm() + (a - d).norm()) / 3;
    out.push_back(inv * ((a + b + d) / 3 + std::sqrt(2.0 / 3.0) * len * n.normalized()));
  }
}

bool SliverRemover::insertAt(TetId t, const Vec3& c) {
  const double xyz[3] = {c.x(), c.y(), c.z()};
  const del3d::LocateResult loc = del3d::locate(s_.mesh, xyz, t, rng_);
  if (loc.status != del3d::LocateStatus::Inside && loc.status != del3d::LocateStatus::OnFace) return false;
  const Metric3d mc = cs_.getMetric(c);
  // A sliver much smaller than the local size (at a small feature of the boundary) takes a
  // point at its own scale: the distance limit is relative to its mean edge length there.
  const std::uint32_t* tv = s_.mesh.tetVertices(t);
  double meanEdge = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      meanEdge += mc.length(s_.mesh.point(VertexId(tv[i])) - s_.mesh.point(VertexId(tv[j]))) / 6;
  const double limit = kSliverInsertDistance * std::min(1.0, meanEdge);
  for (int i = 0; i < 4; ++i)
    if (mc.length(s_.mesh.point(s_.mesh.vertex(loc.tet, i)) - c) < limit) return false;
  del3d::InsertOptions io;
  io.start = loc.tet;
  io.transform = &mc.matrix();
  io.mustRemove = t;
  const del3d::InsertResult r = inserter_.insert(c, io);
  if (r.status != del3d::InsertStatus::Inserted) return false;
  s_.node.resize(s_.mesh.numVertices(), -1);
  vm_.sync();
  ++stats.insertions;
  if (mover_.relocate(r.vertex)) ++stats.moves;
  vertexStar(s_.mesh, r.vertex, star_);
  for (const TetId u : std::vector<TetId>(star_))
    if (isSliver(u)) flipAway(u);
  return true;
}

bool SliverRemover::insertPoint(TetId t) {
  std::vector<Vec3> points;
  candidates(t, points);
  for (const Vec3& c : points)
    if (insertAt(t, c)) return true;
  return false;
}

// Step 4: the sliver and some neighbours replaced by the star of a new vertex
// (SliverSteinerPoint.h), which is then relocated; then flips of the slivers of its star.
bool SliverRemover::steinerPoint(TetId t) {
  created_.clear();
  const VertexId v = insertSteinerPointAtSliver(s_, vm_, t, created_);
  if (!v.valid()) return false;
  ++stats.steinerPoints;
  // the point was chosen among a few candidates: a few relocation steps refine it
  for (int k = 0; k < kSteinerRelocations && mover_.relocate(v); ++k) ++stats.moves;
  vertexStar(s_.mesh, v, star_);
  for (const TetId u : std::vector<TetId>(star_))
    if (isSliver(u)) flipAway(u);
  return true;
}

bool SliverRemover::attack(TetId t) {
  if (flipAway(t) || removeEdges(t)) return true;
  std::uint32_t tv[4];
  std::copy_n(s_.mesh.tetVertices(t), 4, tv);
  for (const std::uint32_t v : tv) {
    if (s_.isFixed(VertexId(v))) continue;
    if (mover_.relocate(VertexId(v))) ++stats.moves;
    if (!isSliver(t)) return true;
  }
  // the free vertices of the neighbours across its faces (their moves reshape its faces'
  // surroundings so that a flip or its own vertices can then act)
  for (int i = 0; i < 4; ++i) {
    const TetId n = s_.mesh.neighbour(t, i);
    if (!n.valid()) continue;
    const VertexId w = s_.mesh.vertex(n, del3d::codeFace(s_.mesh.adjacentCode(t, i)));
    if (s_.isFixed(w)) continue;
    if (mover_.relocate(w)) ++stats.moves;
    if (!isSliver(t) || flipAway(t)) return true;
  }
  // its own free vertices again, for its dihedral angles rather than the mean ratio
  for (const std::uint32_t v : tv) {
    if (!s_.mesh.isAlive(t)) return true;
    if (s_.isFixed(VertexId(v))) continue;
    if (mover_.relocate(VertexId(v), true)) ++stats.moves;
    if (!isSliver(t)) return true;
  }
  if (!s_.mesh.isAlive(t)) return true;
  if (insertion_ && (insertPoint(t) || steinerPoint(t))) return true;
  return reconnect(t);
}

std::vector<TetId> SliverRemover::round(const std::vector<TetId>& slivers) {
  std::vector<TetId> left;
  for (const TetId t : slivers) {
    if (!isSliver(t)) continue;  // removed by an earlier attack (or its slot reused by a good tet)
    attack(t);
    if (isSliver(t)) left.push_back(t);
  }
  return left;
}

}  // namespace

std::vector<TetId> liveSlivers(const SolidTetMesh& s, const VertexMetrics& vm, double angleDeg, double euclideanDeg,
                               const TetScores* scores) {
  const VertexMetrics::SliverAngles a(angleDeg, euclideanDeg);
  std::vector<TetId> out;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k) {
    const TetId t(k);
    if (!s.mesh.isAlive(t)) continue;
    // the cached score of an isotropic tet is its Euclidean η³, which isSliver tests first
    if (scores && (*scores)[t] > a.etaIsotropic && vm.isIsotropic(s.mesh.tetVertices(t))) continue;
    if (vm.isSliver(t, a)) out.push_back(t);
  }
  return out;
}

std::size_t countSlivers(const SolidTetMesh& s, const VertexMetrics& vm, double angleDeg, double euclideanDeg) {
  const VertexMetrics::SliverAngles a(angleDeg, euclideanDeg);
  std::size_t n = 0;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k)
    if (s.mesh.isAlive(TetId(k)) && vm.isSliver(TetId(k), a)) ++n;
  return n;
}

SliverStats removeSlivers(SolidTetMesh& s, const ControlSpace3d& cs, VertexMetrics& vm, double angleDeg,
                          double euclideanDeg, int rounds, bool insertion, const TetScores* scores) {
  // The live slivers, rescanned after each round (the only whole-mesh scans).
  std::vector<TetId> current = liveSlivers(s, vm, angleDeg, euclideanDeg, scores);
  // a solid made of slivers is thinner than its elements: a point inserted there only
  // makes more flat tets, the rounds in the metric only shuffle them (header)
  const bool film = static_cast<double>(current.size()) > kFilmSliverShare * static_cast<double>(s.mesh.numTets());
  if (film) insertion = false;
  SliverRemover r(s, cs, vm, angleDeg, euclideanDeg, insertion);
  r.stats.before = current.size();
  vm.setGuardEuclidean(true);
  // Later rounds visit every sliver again: the operators (insertions, Steiner points) make
  // new tets, some of them slivers, that the previous round's list does not hold.
  for (int i = 0; i < rounds && !current.empty() && !film; ++i) {
    r.round(current);
    ++r.stats.metricRounds;
    std::vector<TetId> left = liveSlivers(s, vm, angleDeg, euclideanDeg);
    logDebug("sliver round " + std::to_string(i + 1) + ": " + std::to_string(current.size()) + " -> " +
             std::to_string(left.size()) + " slivers of " + std::to_string(s.mesh.numTets()) + " tets");
    const bool progress = left.size() < current.size();
    current = std::move(left);
    if (!progress) break;
  }
  // The referee's slivers last: the operators on the metric slivers above make new tets,
  // some flat in space, after their slots were visited; rounds over the Euclidean slivers
  // alone (a few) while they go down. They are among `current` (a Euclidean sliver is a
  // sliver for any metric angle ≥ 0), in slot order.
  SliverRemover e(s, cs, vm, 0.0, euclideanDeg, insertion);
  const VertexMetrics::SliverAngles euclidean(0.0, euclideanDeg);
  std::vector<TetId> slivers;
  for (const TetId t : current)
    if (vm.isSliver(t, euclidean)) slivers.push_back(t);
  const bool changed = !slivers.empty();
  for (int i = 0; i < rounds && !slivers.empty(); ++i) {
    e.round(slivers);
    std::vector<TetId> left = liveSlivers(s, vm, 0.0, euclideanDeg);
    if (left.size() >= slivers.size()) break;
    slivers = std::move(left);
  }
  r.stats.merge(e.stats);
  vm.setGuardEuclidean(false);
  r.stats.after = changed ? countSlivers(s, vm, angleDeg, euclideanDeg) : current.size();
  return r.stats;
}

}  // namespace aniso::improve3d
