#include "mesher/volume/improve/QualityFlips.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <type_traits>

#include "mesher/delaunay3d/EdgeRing.h"
#include "mesher/delaunay3d/FlipT23.h"
#include "mesher/delaunay3d/FlipT32.h"
#include "mesher/delaunay3d/FlipT44.h"

namespace aniso::improve3d {
namespace {

using del3d::VertexId;
constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

}  // namespace

/// Worst score (η_M³) over tets given as ids (cached when there is a cache) or as vertex
/// quadruples.
template <class Range>
double QualityFlips::worst(const Range& tets) const {
  double w = 1e300;
  for (const auto& t : tets) {
    if constexpr (std::is_same_v<std::decay_t<decltype(t)>, del3d::TetId>)
      w = std::min(w, score(t));
    else
      w = std::min(w, vm_.score(t));
  }
  return w;
}

/// Records the tets made by a flip: appended to `out`, measured into the cache.
template <std::size_t N>
void QualityFlips::created(const std::array<del3d::TetId, N>& tets, std::vector<del3d::TetId>& out) {
  out.insert(out.end(), tets.begin(), tets.end());
  if (scores_)
    for (const del3d::TetId t : tets) scores_->update(t);
  if (!createdAt_.empty()) {
    createdAt_.resize(s_.mesh.tetSlots(), 0);
    failedAt_.resize(s_.mesh.tetSlots(), 0);
    for (const del3d::TetId t : tets) createdAt_[t.index] = epoch() + 1;  // the flip is counted after this
  }
}

bool QualityFlips::triedBefore(std::span<const del3d::TetId> tets) const {
  if (createdAt_.empty()) return false;
  for (const del3d::TetId r : tets) {
    const std::uint32_t f = failedAt_[r.index];
    if (f == 0 || f < createdAt_[r.index]) continue;  // no failed visit of this tet
    if (std::all_of(tets.begin(), tets.end(), [&](del3d::TetId q) { return createdAt_[q.index] <= f; })) return true;
  }
  return false;
}

// Floating-point prefilters (quality first, then the exact legality of the kernel's
// can*(): most candidate flips fail on quality, which costs no exact predicate).

namespace {
using Quad = std::array<VertexId, 4>;
/// The smallest score of the tets (|η_M³| with `absolute`: whatever the orientation, the
/// legality check rejects inverted ones), or the first one not above `before` (a flip to
/// these tets cannot beat `before` then: the rest need not be measured).
template <std::size_t N>
double worstAbove(const VertexMetrics& vm, const std::array<Quad, N>& tets, double before, bool absolute) {
  double w = 1e300;
  for (const Quad& q : tets) {
    const double e = absolute ? std::abs(vm.score(q)) : vm.score(q);
    if (!(e > before)) return e;
    w = std::min(w, e);
  }
  return w;
}
}  // namespace

bool QualityFlips::tryFace(del3d::TetId t, int i, std::vector<del3d::TetId>& created) {
  if (s_.mesh.isConstrained(t, i) || !s_.mesh.neighbour(t, i).valid()) return false;
  {
    const del3d::TetId u = s_.mesh.neighbour(t, i);
    const del3d::TetId pair[2] = {t, u};
    if (triedBefore(pair)) return false;
    const VertexId d = s_.mesh.vertex(t, i), e = s_.mesh.vertex(u, del3d::codeFace(s_.mesh.adjacentCode(t, i)));
    VertexId f[3];
    for (int m = 0; m < 3; ++m) f[m] = s_.mesh.vertex(t, del3d::kFaceVertex[i][m]);
    // (f0, f1, f2, d) is positive; the new tets replace one f by e.
    const double before = std::min(score(t), score(u));
    const std::array<Quad, 3> next{Quad{f[0], f[1], e, d}, Quad{f[1], f[2], e, d}, Quad{f[2], f[0], e, d}};
    if (!beatsWorst(worstAbove(vm_, next, before, false), before, gain_)) return false;
  }
  del3d::Flip23Plan plan;
  if (!del3d::canFlip23(s_.mesh, t, i, &plan)) return false;
  if (!(beatsWorst(worst(plan.newTets), worst(plan.oldTets), gain_))) return false;
  this->created(del3d::flip23(s_.mesh, plan), created);
  ++counts_.f23;
  return true;
}

bool QualityFlips::tryEdge(del3d::TetId t, int i, int j, std::vector<del3d::TetId>& created) {
  std::array<del3d::TetId, 4> ring;
  std::array<del3d::VertexId, 4> apex;
  const int n = del3d::closedEdgeRing(s_.mesh, t, i, j, ring, apex);
  if (n < 3 || n > 4 || triedBefore(std::span<const del3d::TetId>(ring.data(), n))) return false;
  const VertexId a = s_.mesh.vertex(t, i), b = s_.mesh.vertex(t, j);
  if (n == 3) {
    const double before = worst(std::span<const del3d::TetId>(ring.data(), 3));
    const std::array<Quad, 2> next{Quad{apex[0], apex[1], apex[2], a}, Quad{apex[0], apex[1], apex[2], b}};
    if (!beatsWorst(worstAbove(vm_, next, before, true), before, gain_)) return false;
    del3d::Flip32Plan plan;
    if (!del3d::canFlip32(s_.mesh, t, i, j, &plan)) return false;
    if (!(beatsWorst(worst(plan.newTets), worst(plan.oldTets), gain_))) return false;
    this->created(del3d::flip32(s_.mesh, plan), created);
    ++counts_.f32;
    return true;
  }
  if (n != 4) return false;
  const double before = worst(ring);
  del3d::Flip44Plan best;
  double bestAfter = before;
  bool found = false;
  for (int diag = 0; diag < 2; ++diag) {
    const VertexId p = apex[diag], q = apex[diag + 1], r = apex[diag + 2], w = apex[(diag + 3) % 4];
    const std::array<Quad, 4> next{Quad{a, p, q, r}, Quad{b, p, q, r}, Quad{a, p, r, w}, Quad{b, p, r, w}};
    if (!beatsWorst(worstAbove(vm_, next, before, true), before, gain_)) continue;
    del3d::Flip44Plan plan;
    if (!del3d::canFlip44(s_.mesh, t, i, j, diag, &plan)) continue;
    const double after = worst(plan.newTets);
    if (after > bestAfter && beatsWorst(after, before, gain_)) bestAfter = after, best = plan, found = true;
  }
  if (!found) return false;
  this->created(del3d::flip44(s_.mesh, best), created);
  ++counts_.f44;
  return true;
}

bool QualityFlips::visit(del3d::TetId t, std::vector<del3d::TetId>& created) {
  if (!s_.mesh.isAlive(t)) return false;
  for (int i = 0; i < 4; ++i)
    if (tryFace(t, i, created)) return true;
  for (const auto& e : kEdges)
    if (tryEdge(t, e[0], e[1], created)) return true;
  return false;
}

void QualityFlips::run(double candidateBelow) {
  std::vector<del3d::TetId> work;
  const double key = candidateBelow * candidateBelow * candidateBelow;
  for (std::uint32_t k = 0; k < s_.mesh.tetSlots(); ++k)
    if (s_.mesh.isAlive(del3d::TetId(k)) && score(del3d::TetId(k)) < key) work.push_back(del3d::TetId(k));
  const std::size_t cap = kMaxFlipsPerTet * work.size() + counts_.total();
  failedAt_.assign(s_.mesh.tetSlots(), 0);
  createdAt_.assign(s_.mesh.tetSlots(), 0);
  // Created tets are visited again only when they are candidates themselves (performance:
  // most flips leave good tets, whose visit finds nothing).
  std::vector<del3d::TetId> created;
  for (std::size_t k = 0; k < work.size() && counts_.total() < cap; ++k) {
    created.clear();
    if (!visit(work[k], created)) {
      if (s_.mesh.isAlive(work[k])) failedAt_[work[k].index] = epoch();
      continue;
    }
    for (const del3d::TetId t : created)
      if (s_.mesh.isAlive(t) && score(t) < key) work.push_back(t);
  }
  failedAt_.clear();
  createdAt_.clear();
}

}  // namespace aniso::improve3d
