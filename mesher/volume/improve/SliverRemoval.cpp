#include "mesher/volume/improve/SliverRemoval.h"

#include <vector>

#include "mesher/delaunay3d/Inserter.h"
#include "mesher/delaunay3d/Locate.h"
#include "mesher/volume/improve/QualityFlips.h"
#include "mesher/volume/improve/TetStar.h"
#include "mesher/volume/improve/VertexMover.h"
#include "mesher/volume/refine/TetMetricGeometry.h"

namespace aniso::improve3d {
namespace {

using del3d::TetId;
using del3d::VertexId;

class SliverRemover {
 public:
  SliverRemover(SolidTetMesh& s, const ControlSpace3d& cs, VertexMetrics& vm, double angle, bool insertion)
      : s_(s), cs_(cs), vm_(vm), angle_(angle), insertion_(insertion), flips_(s, vm, 0.0), mover_(s, vm),
        inserter_(s.mesh, 0x51F3A7u) {}

  /// One round; returns the number of slivers it visited that are gone.
  std::size_t round();
  SliverStats stats;

 private:
  bool isSliver(TetId t) const { return s_.mesh.isAlive(t) && vm_.metricMinDihedral(t) < angle_; }
  bool attack(TetId t);
  bool flipAway(TetId t);
  bool insertCentre(TetId t);

  SolidTetMesh& s_;
  const ControlSpace3d& cs_;
  VertexMetrics& vm_;
  double angle_;
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

bool SliverRemover::insertCentre(TetId t) {
  const std::uint32_t* tv = s_.mesh.tetVertices(t);
  const Mat3 m = vm_.tetMetric(tv);
  Vec3 c;
  if (!refine3d::metricCircumcentre(m, s_.mesh.point(VertexId(tv[0])), s_.mesh.point(VertexId(tv[1])),
                                    s_.mesh.point(VertexId(tv[2])), s_.mesh.point(VertexId(tv[3])), c))
    return false;
  const double xyz[3] = {c.x(), c.y(), c.z()};
  const del3d::LocateResult loc = del3d::locate(s_.mesh, xyz, t, rng_);
  if (loc.status != del3d::LocateStatus::Inside && loc.status != del3d::LocateStatus::OnFace) return false;
  const Metric3d mc = cs_.getMetric(c);
  for (int i = 0; i < 4; ++i)
    if (mc.length(s_.mesh.point(s_.mesh.vertex(loc.tet, i)) - c) < kSliverInsertDistance) return false;
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

bool SliverRemover::attack(TetId t) {
  if (flipAway(t)) return true;
  std::uint32_t tv[4];
  std::copy_n(s_.mesh.tetVertices(t), 4, tv);
  for (const std::uint32_t v : tv) {
    if (s_.isFixed(VertexId(v))) continue;
    if (mover_.relocate(VertexId(v))) ++stats.moves;
    if (!isSliver(t)) return true;
  }
  return insertion_ && insertCentre(t);
}

std::size_t SliverRemover::round() {
  std::vector<TetId> slivers;
  for (std::uint32_t k = 0; k < s_.mesh.tetSlots(); ++k)
    if (isSliver(TetId(k))) slivers.push_back(TetId(k));
  std::size_t gone = 0;
  for (const TetId t : slivers) {
    if (!isSliver(t)) continue;  // removed by an earlier attack (or its slot reused by a good tet)
    attack(t);
    if (!isSliver(t)) ++gone;
  }
  return gone;
}

}  // namespace

std::size_t countSlivers(const SolidTetMesh& s, const VertexMetrics& vm, double angleDeg) {
  std::size_t n = 0;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k)
    if (s.mesh.isAlive(TetId(k)) && vm.metricMinDihedral(TetId(k)) < angleDeg) ++n;
  return n;
}

SliverStats removeSlivers(SolidTetMesh& s, const ControlSpace3d& cs, VertexMetrics& vm, double angleDeg, int rounds,
                          bool insertion) {
  SliverRemover r(s, cs, vm, angleDeg, insertion);
  r.stats.before = countSlivers(s, vm, angleDeg);
  for (int i = 0; i < rounds && r.round() > 0; ++i) {
  }
  r.stats.after = countSlivers(s, vm, angleDeg);
  return r.stats;
}

}  // namespace aniso::improve3d
