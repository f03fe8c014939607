#include "mesher/volume/PipeReduction.h"

#include <vector>

#include "mesher/volume/LocalChange.h"
#include "mesher/volume/MeshQueries.h"
#include "mesher/volume/Pipe.h"

namespace aniso::volume {

using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

namespace {

/// Bound on the face flips tried in the lookahead per step (the region can be large).
constexpr std::size_t kMaxLookaheadFaces = 256;
/// Bound on the changes tried (applied, measured, undone) for one entity: a step's lookahead
/// tries up to kMaxLookaheadFaces face flips, each followed by every single change of the
/// new pipe, and in a nearly degenerate region every trial runs exact arithmetic. Without
/// it a real assembly (Push_SMD_6.2x6.2mm) spent minutes in pipe reduction (every gdb
/// sample over a minute in Reducer::step); an entity over budget is left to the Steiner
/// points of the next phase.
constexpr std::uint64_t kMaxTrialsPerEntity = 50000;

class Reducer {
 public:
  Reducer(TetMesh& mesh, std::function<void(Pipe&)> measure, const EdgeGuard& guard, FlipCounters& counters)
      : mesh_(mesh), measure_(std::move(measure)), guard_(guard), counters_(counters),
        budgetEnd_(counters.tried + kMaxTrialsPerEntity) {}

  /// The entity's trials are spent (kMaxTrialsPerEntity).
  bool exhausted() const { return counters_.tried >= budgetEnd_; }

  /// One kept change (or two with lookahead) lowering the weight; false when none helps.
  bool step() {
    Pipe pipe;
    measure_(pipe);
    if (pipe.degenerate) return false;
    const int w0 = pipe.weight();
    if (w0 == 0) return false;
    std::vector<LocalPlan> plans;
    candidatePlans(pipe, true, plans);
    for (const LocalPlan& p : plans)
      if (tryPlan(p, w0)) return true;
    // Lookahead: a face flip in the region, then any single change.
    std::size_t tried = 0;
    for (const TetId t : pipe.tets) {
      if (exhausted()) return false;
      for (int f = 0; f < 4 && tried < kMaxLookaheadFaces; ++f) {
        if (!mesh_.isAlive(t)) break;
        del3d::Flip23Plan fp;
        if (!del3d::canFlip23(mesh_, t, f, &fp)) continue;
        ++tried;
        ++counters_.tried;
        const AppliedChange first = applyPlan(mesh_, toPlan(mesh_, fp));
        Pipe after;
        measure_(after);
        if (!after.degenerate && after.weight() < w0) {
          ++counters_.flips23;
          return true;
        }
        std::vector<LocalPlan> next;
        if (!after.degenerate) candidatePlans(after, false, next);
        for (const LocalPlan& p : next) {
          if (tryPlan(p, w0)) {
            ++counters_.flips23;
            return true;
          }
        }
        undoChange(mesh_, first);
      }
    }
    return false;
  }

 private:
  void candidatePlans(const Pipe& pipe, bool withFaces, std::vector<LocalPlan>& out) {
    if (withFaces) {
      for (const FaceRef& f : pipe.faces) {
        del3d::Flip23Plan fp;
        if (del3d::canFlip23(mesh_, f.tet, f.face, &fp)) out.push_back(toPlan(mesh_, fp));
      }
    }
    for (const EdgeRef& e : pipe.edges) {
      if (guard_ && guard_(mesh_.vertex(e.tet, e.i), mesh_.vertex(e.tet, e.j))) continue;
      const int n = removalRingSize(mesh_, e.tet, e.i, e.j);
      for (int s = 0; s < n; ++s) {
        LocalPlan p;
        if (canRemoveEdge(mesh_, e.tet, e.i, e.j, s, &p)) out.push_back(std::move(p));
      }
    }
  }

  bool tryPlan(const LocalPlan& p, int w0) {
    if (!planCurrent(mesh_, p)) return false;  // stale after an earlier change
    ++counters_.tried;
    const AppliedChange c = applyPlan(mesh_, p);
    Pipe after;
    measure_(after);
    if (!after.degenerate && after.weight() < w0) {
      (p.oldTets.size() == 2 ? counters_.flips23 : counters_.removals) += 1;
      return true;
    }
    undoChange(mesh_, c);
    return false;
  }

  TetMesh& mesh_;
  std::function<void(Pipe&)> measure_;
  const EdgeGuard& guard_;
  FlipCounters& counters_;
  std::uint64_t budgetEnd_;
};

}  // namespace

bool reduceEdgePipe(TetMesh& mesh, VertexId a, VertexId b, const EdgeGuard& guard, int maxChanges,
                    FlipCounters& counters) {
  std::vector<TetId> star;
  if (findEdge(mesh, a, b, star).valid()) return true;
  Reducer r(mesh, [&](Pipe& p) { segmentPipe(mesh, a, b, p); }, guard, counters);
  for (int k = 0; k < maxChanges && !r.exhausted(); ++k) {
    if (!r.step()) break;
    if (findEdge(mesh, a, b, star).valid()) return true;
  }
  return findEdge(mesh, a, b, star).valid();
}

bool reduceFacePipe(TetMesh& mesh, VertexId a, VertexId b, VertexId c, const EdgeGuard& guard, int maxChanges,
                    FlipCounters& counters) {
  std::vector<TetId> star;
  if (findFace(mesh, a, b, c, star).valid()) return true;
  Reducer r(mesh, [&](Pipe& p) { trianglePipe(mesh, a, b, c, p); }, guard, counters);
  for (int k = 0; k < maxChanges && !r.exhausted(); ++k) {
    if (!r.step()) break;
    if (findFace(mesh, a, b, c, star).valid()) return true;
  }
  return findFace(mesh, a, b, c, star).valid();
}

}  // namespace aniso::volume
