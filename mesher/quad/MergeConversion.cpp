#include "mesher/quad/MergeConversion.h"

#include <algorithm>
#include <array>
#include <limits>
#include <queue>
#include <set>
#include <tuple>

#include "mesher/quad/OddSplit.h"
#include "mesher/quad/RegionParity.h"

namespace aniso::quad {
namespace {

struct Entry {
  double rank;
  int e, k, stamp, deferrals;
  bool operator>(const Entry& o) const { return std::tie(rank, e, k) > std::tie(o.rank, o.e, o.k); }
};

struct Candidate {
  double quality;
  int j;       ///< edge of the base triangle shared with the neighbour
  int other;   ///< the neighbour
  Corners quad;
};

class Merger {
 public:
  Merger(QuadMesh2d& mesh, VertexMetrics& metrics, const MergeOptions& o) : mesh_(mesh), metrics_(metrics), o_(o) {}

  MergeStats run() {
    onFront_.assign(mesh_.boundary.begin(), mesh_.boundary.end());
    for (int e = 0; e < mesh_.numElements(); ++e)
      if (mesh_.isTriangle(e)) {
        push(e);
        ++maxTransitions_;
      }
    // The transitions keep the region's triangles (they add quads around it): at most one
    // per triangle of the start, so that the conversion always ends.
    plainMorph_ = o_.morph;
    plainMorph_.transitionSeam.seamRatio = plainMorph_.transitionSplit.splitRatio = std::numeric_limits<double>::infinity();
    while (!heap_.empty()) {
      const Entry x = heap_.top();
      heap_.pop();
      if (!mesh_.isTriangle(x.e) || stamp_[x.e] != x.stamp || !isFrontEdge(mesh_, x.e, x.k)) continue;
      step(x);
    }
    for (int e = 0; e < mesh_.numElements(); ++e) stats_.triangles += mesh_.isTriangle(e);
    return stats_;
  }

 private:
  void grow() {
    stamp_.resize(mesh_.numElements(), 0);
    level_.resize(mesh_.numElements(), 0);
    onFront_.resize(mesh_.numVertices(), 0);
  }

  int frontLevel(int e, int k) const {
    const int f = mesh_.adj[e][k];
    return f == kNone ? 0 : level_[f] + 1;
  }

  /// (Re)classifies every front edge of triangle e.
  void push(int e, int deferrals = 0, double penalty = 0) {
    grow();
    for (int k = 0; k < 3; ++k) {
      if (!isFrontEdge(mesh_, e, k)) continue;
      const FrontEdgeClass c = classifyFrontEdge(mesh_, metrics_, e, k, frontLevel(e, k), o_.weights);
      heap_.push({c.rank + penalty, e, k, stamp_[e], deferrals});
    }
  }

  std::vector<Candidate> candidates(int e, int k) {
    std::vector<Candidate> out;
    const Corners& c = mesh_.corners[e];
    for (int j : {(k + 1) % 3, (k + 2) % 3}) {
      const int t2 = mesh_.adj[e][j];
      if (t2 == kNone || !mesh_.isTriangle(t2)) continue;
      const int u = c[j], v = c[(j + 1) % 3], x = c[(j + 2) % 3];
      const int i = mesh_.edgeIndex(t2, v, u);
      if (i == kNone) continue;
      const Corners quad{u, mesh_.corners[t2][(i + 2) % 3], v, x};
      const double q = elementQuality(mesh_, metrics_, quad);
      if (q >= o_.minQuality) out.push_back({q, j, t2, quad});
    }
    std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
      return a.quality != b.quality ? a.quality > b.quality : a.j < b.j;
    });
    return out;
  }

  bool useMorph(int e, int k, int level) {
    if (o_.method == QuadMethod::Merge) return false;
    if (o_.method == QuadMethod::Morph || level <= o_.nearBoundaryLevels) return true;
    return metrics_.gradation(mesh_.corners[e][k], mesh_.corners[e][(k + 1) % 3]) <= o_.lowGradation;
  }

  /// A morphing step for front edge k of e; true when it changed the front (a quad or a
  /// seam). The triangles it made (swaps, seam) are classified.
  bool morph(int e, int k, int level) {
    const int n0 = mesh_.numElements();
    const bool transitions = stats_.transitionSeams + stats_.transitionSplits < maxTransitions_;
    const MorphResult m = morphFrontEdge(mesh_, metrics_, e, k, onFront_, parity_, transitions ? o_.morph : plainMorph_);
    grow();
    for (int f = n0; f < mesh_.numElements(); ++f)
      if (mesh_.isTriangle(f)) push(f);
    if (m.quad != kNone) {
      ++stats_.morphed;
      created(m.quad, level);
      return true;
    }
    if (m.transition.done) {
      // The quad behind the long edge was reshaped (and split): its level goes on.
      const TransitionResult& t = m.transition;
      ++(m.split ? stats_.transitionSplits : stats_.transitionSeams);
      level_[t.reshaped] = level_[t.from];
      if (t.extra != kNone) {
        level_[t.extra] = level_[t.from];
        ++stats_.quads;
      }
      created(t.quad, level);
      return true;
    }
    if (m.seamVertex == kNone) {
      ++stats_.morphFailures[static_cast<int>(m.failure)];
      return false;
    }
    ++stats_.seams;
    onFront_[m.seamVertex] = 1;
    return true;
  }

  void step(const Entry& x) {
    int e = x.e, k = x.k;
    const int level = frontLevel(e, k);
    const int a = mesh_.corners[e][k], b = mesh_.corners[e][(k + 1) % 3];
    // Morphing is tried once per front edge (its failed swaps must not cycle).
    if (useMorph(e, k, level) && morphTried_.insert({a, b}).second) {
      if (morph(e, k, level)) return;
      // Fall back to merging, on the base triangle as the failed step's swaps left it.
      if (!mesh_.isTriangle(e) || mesh_.edgeIndex(e, a, b) == kNone) {
        e = kNone;
        for (int f = mesh_.numElements() - 1; f >= 0 && e == kNone && f >= mesh_.numElements() - 64; --f)
          if (mesh_.isTriangle(f) && mesh_.edgeIndex(f, a, b) != kNone) e = f;
        if (e == kNone) return;
        k = mesh_.edgeIndex(e, a, b);
      }
    }
    const int apex = mesh_.corners[e][(k + 2) % 3];
    const std::vector<Candidate> cands = candidates(e, k);
    if (cands.empty()) {
      ++stats_.rejected;
      return;
    }
    for (const Candidate& c : cands) {
      const int d = c.quad[1];  // the neighbour's apex
      if ((!onFront_[apex] && !onFront_[d]) || parity_.mergeKeepsParity(mesh_, e, c.other)) {
        merge(e, c, level);
        return;
      }
    }
    if (!onFront_[apex]) {
      for (const Candidate& c : cands) {
        const OddSplitResult r = splitAndMerge(mesh_, metrics_, e, c.j, o_.minQuality);
        if (!r.done) continue;
        ++stats_.oddSplits;
        created(r.quad, level);
        return;
      }
    }
    if (onFront_[apex]) {
      for (const Candidate& c : cands) {
        if (onFront_[c.quad[1]]) continue;  // the neighbour's apex d must be free too
        const OddSplitResult r = splitEdgeAndMerge(mesh_, metrics_, e, k, c.j, o_.minQuality);
        if (!r.done) continue;
        ++stats_.edgeSplits;
        created(r.quad, level);
        return;
      }
    }
    if (x.deferrals < o_.maxDeferrals) {
      ++stats_.deferred;
      ++stamp_[e];
      push(e, x.deferrals + 1, 100.0 * (x.deferrals + 1));
      return;
    }
    ++stats_.forcedOdd;
    merge(e, cands.front(), level);
  }

  void merge(int e, const Candidate& c, int level) {
    const std::array<int, 2> removed{e, c.other};
    const std::array<Corners, 1> added{c.quad};
    created(mesh_.replacePatch(removed, added)[0], level);
  }

  /// Bookkeeping after quad q was formed: its level, its corners on the front, and the
  /// front edges around its corners reclassified.
  void created(int q, int level) {
    grow();
    ++stats_.quads;
    level_[q] = level;
    std::vector<int> around;
    for (int i = 0; i < 4; ++i) {
      const int v = mesh_.corners[q][i];
      onFront_[v] = 1;
      around.clear();
      bool closed = false;
      mesh_.star(v, q, around, closed);
      for (int t : around) {
        if (!mesh_.isTriangle(t)) continue;
        ++stamp_[t];
        push(t);
      }
    }
  }

  QuadMesh2d& mesh_;
  VertexMetrics& metrics_;
  const MergeOptions& o_;
  MergeStats stats_;
  RegionParity parity_;
  std::set<std::pair<int, int>> morphTried_;
  MorphOptions plainMorph_;  ///< o_.morph without the transitions
  int maxTransitions_ = 0;
  std::vector<int> stamp_, level_;
  std::vector<std::uint8_t> onFront_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap_;
};

}  // namespace

MergeStats mergeFront(QuadMesh2d& mesh, VertexMetrics& metrics, const MergeOptions& options) {
  return Merger(mesh, metrics, options).run();
}

}  // namespace aniso::quad
