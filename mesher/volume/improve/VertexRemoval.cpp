#include "mesher/volume/improve/VertexRemoval.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include "mesher/core/Error.h"
#include "mesher/delaunay3d/Delaunay3d.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/volume/RegionReplace.h"
#include "mesher/volume/improve/TetStar.h"

namespace aniso::improve3d {
namespace {

using del3d::TetId;
using del3d::VertexId;
constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

/// Sorted vertex triple of a face, as one key (21 bits would not do: ids are 32-bit).
struct FaceKey {
  std::array<std::uint32_t, 3> v;
  bool operator==(const FaceKey&) const = default;
};
struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    return (std::size_t{k.v[0]} * 0x9E3779B97F4A7C15ull) ^ (std::size_t{k.v[1]} * 0xC2B2AE3D27D4EB4Full) ^ k.v[2];
  }
};
FaceKey faceKey(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  FaceKey k{{a, b, c}};
  std::sort(k.v.begin(), k.v.end());
  return k;
}


}  // namespace

double VertexRemoval::worstAbove(const std::vector<Quad>& tets, double floor) const {
  double w = 1e300;
  for (const Quad& q : tets) {
    const std::uint32_t ids[4] = {q[0].index, q[1].index, q[2].index, q[3].index};
    const double e = vm_.score(ids);
    if (!(e > floor)) return e;
    if (!vm_.certifiesOrientation(ids, e) &&
        !(predicates::orient3d(s_.mesh.coords(q[0]), s_.mesh.coords(q[1]), s_.mesh.coords(q[2]),
                               s_.mesh.coords(q[3])) > 0))
      return -1;
    w = std::min(w, e);
  }
  return w;
}

bool VertexRemoval::guardKept() {
  const bool was = vm_.guardEuclidean();
  vm_.setGuardEuclidean(true);
  double before = 1e300, after = 1e300;
  for (const TetId t : star_) before = std::min(before, vm_.score(t));
  for (const Quad& q : best_) after = std::min(after, vm_.score(q));
  vm_.setGuardEuclidean(was);
  return after >= before;
}

bool VertexRemoval::meanKept() const {
  double before = 0, after = 0;
  for (const TetId t : star_) before += std::cbrt(score(t));
  for (const Quad& q : best_) after += std::cbrt(vm_.score(q));
  // the mesh's mean η_M does not drop: after − before ≥ mean · (new count − old count)
  return after - before >= meanEta_ * (static_cast<double>(best_.size()) - static_cast<double>(star_.size()));
}

bool VertexRemoval::edgesShortEnough(const std::vector<Quad>& tets, double maxLength) const {
  for (const Quad& q : tets)
    for (const auto& e : kEdges) {
      const VertexId a = q[e[0]], b = q[e[1]];
      if (s_.isFixed(a) && s_.isFixed(b)) continue;
      if (std::binary_search(linkEdges_.begin(), linkEdges_.end(), edgeKey(a.index, b.index))) continue;
      const Vec3 d = s_.mesh.point(b) - s_.mesh.point(a);
      if ((0.5 * (vm_.at(a) + vm_.at(b)) * d).norm() > maxLength) return false;
    }
  return true;
}

bool VertexRemoval::delaunayFill(VertexId v, std::vector<Quad>& out) {
  out.clear();
  points_.clear();
  for (const VertexId w : link_) points_.push_back(s_.mesh.point(w));
  del3d::DelaunayOptions opt;
  opt.spatialSort = false;  // a few tens of points: the input order, deterministic
  opt.transform = vm_.at(v);
  opt.reserve = false;
  // The kernel throws MeshingError when it cannot build the enclosing box (a strongly
  // anisotropic transform over a few points: thin plates at the defaults); then the fill is
  // tried in space, and failing that there is no fill (not an error of the mesh).
  del3d::DelaunayResult r;
  try {
    r = del3d::buildDelaunay(scratch_, points_, opt);
  } catch (const MeshingError&) {
    opt.transform = Mat3::Identity();
    try {
      r = del3d::buildDelaunay(scratch_, points_, opt);
    } catch (const MeshingError&) {
      return false;
    }
  }
  if (r.inserted != link_.size()) return false;
  // scratch vertex -> mesh vertex (box corners: none)
  std::vector<std::uint32_t> toMesh(scratch_.numVertices(), del3d::kNone);
  for (std::size_t i = 0; i < link_.size(); ++i) toMesh[r.vertexOf[i].index] = link_[i].index;
  std::unordered_map<FaceKey, std::size_t, FaceKeyHash> linkFace;  // link face -> its index
  std::unordered_set<FaceKey, FaceKeyHash> seen;                   // link faces found, from inside
  for (std::size_t k = 0; k < linkFaces_.size(); ++k) {
    const Quad& q = linkFaces_[k].tet;
    const int i = linkFaces_[k].slot;
    linkFace[faceKey(q[(i + 1) & 3].index, q[(i + 2) & 3].index, q[(i + 3) & 3].index)] = k;
  }
  std::vector<std::uint32_t> seeds;
  std::vector<std::uint8_t> inside(scratch_.tetSlots(), 0);
  for (std::uint32_t t = 0; t < scratch_.tetSlots(); ++t) {
    if (!scratch_.isAlive(TetId(t))) continue;
    const std::uint32_t* tv = scratch_.tetVertices(TetId(t));
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t a = toMesh[tv[del3d::kFaceVertex[i][0]]], b = toMesh[tv[del3d::kFaceVertex[i][1]]],
                          c = toMesh[tv[del3d::kFaceVertex[i][2]]];
      if (a == del3d::kNone || b == del3d::kNone || c == del3d::kNone) continue;
      const auto it = linkFace.find(faceKey(a, b, c));
      if (it == linkFace.end() || toMesh[tv[i]] == del3d::kNone) continue;
      // inside when the opposite vertex is on v's side of the link face
      Quad q = linkFaces_[it->second].tet;
      q[linkFaces_[it->second].slot] = VertexId(toMesh[tv[i]]);
      if (predicates::orient3d(s_.mesh.coords(q[0]), s_.mesh.coords(q[1]), s_.mesh.coords(q[2]),
                               s_.mesh.coords(q[3])) > 0) {
        seen.insert(it->first);
        if (!inside[t]) {
          inside[t] = 1;
          seeds.push_back(t);
        }
      }
    }
  }
  if (seen.size() != linkFace.size()) return false;  // a link face is not in the triangulation
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const TetId t(seeds[k]);
    const std::uint32_t* tv = scratch_.tetVertices(t);
    for (int i = 0; i < 4; ++i) {
      if (toMesh[tv[i]] == del3d::kNone) return false;  // a box corner: outside the link
      const std::uint32_t a = toMesh[tv[del3d::kFaceVertex[i][0]]], b = toMesh[tv[del3d::kFaceVertex[i][1]]],
                          c = toMesh[tv[del3d::kFaceVertex[i][2]]];
      if (a != del3d::kNone && b != del3d::kNone && c != del3d::kNone && linkFace.count(faceKey(a, b, c))) continue;
      const TetId n = scratch_.neighbour(t, i);
      if (!n.valid()) return false;
      if (!inside[n.index]) {
        inside[n.index] = 1;
        seeds.push_back(n.index);
      }
    }
  }
  for (const std::uint32_t t : seeds) {
    const std::uint32_t* tv = scratch_.tetVertices(TetId(t));
    out.push_back({VertexId(toMesh[tv[0]]), VertexId(toMesh[tv[1]]), VertexId(toMesh[tv[2]]), VertexId(toMesh[tv[3]])});
  }
  return true;
}

bool VertexRemoval::loadRegion(std::span<const VertexId> remove, std::size_t maxTets) {
  star_.clear();
  for (const VertexId v : remove) {
    vertexStar(s_.mesh, v, scratchStar_);
    if (scratchStar_.empty()) return false;
    for (const TetId t : scratchStar_)
      if (std::find(star_.begin(), star_.end(), t) == star_.end()) star_.push_back(t);
    if (star_.size() > maxTets) return false;
  }
  linkFaces_.clear();
  link_.clear();
  linkEdges_.clear();
  for (const TetId t : star_) {
    const std::uint32_t* tv = s_.mesh.tetVertices(t);
    for (int i = 0; i < 4; ++i) {
      const TetId n = s_.mesh.neighbour(t, i);
      if (n.valid() && std::find(star_.begin(), star_.end(), n) != star_.end()) continue;
      linkFaces_.push_back({{VertexId(tv[0]), VertexId(tv[1]), VertexId(tv[2]), VertexId(tv[3])}, i});
      const std::uint32_t f[3] = {tv[del3d::kFaceVertex[i][0]], tv[del3d::kFaceVertex[i][1]], tv[del3d::kFaceVertex[i][2]]};
      for (int k = 0; k < 3; ++k) {
        if (std::find(link_.begin(), link_.end(), VertexId(f[k])) == link_.end()) link_.push_back(VertexId(f[k]));
        linkEdges_.push_back(edgeKey(f[k], f[(k + 1) % 3]));
      }
    }
  }
  // every removed vertex inside the region (its whole star in it), none on the link
  for (const VertexId v : remove)
    if (std::find(link_.begin(), link_.end(), v) != link_.end()) return false;
  std::sort(linkEdges_.begin(), linkEdges_.end());
  linkEdges_.erase(std::unique(linkEdges_.begin(), linkEdges_.end()), linkEdges_.end());
  return true;
}

bool VertexRemoval::retriangulate(VertexId v, const VertexRemovalOptions& o, bool collapses) {
  double before = 1e300;
  for (const TetId t : star_) before = std::min(before, score(t));
  // the bar: beat the region's worst by the gain
  double bestWorst = std::pow(std::cbrt(std::max(before, 0.0)) + o.gain, 3);
  bool found = false;
  if (collapses)
    for (const VertexId w : link_) {
      trial_.clear();
      for (const LinkFace& f : linkFaces_) {
        if (std::find(f.tet.begin(), f.tet.end(), w) != f.tet.end()) continue;
        Quad n = f.tet;
        n[f.slot] = w;
        trial_.push_back(n);
      }
      const double w3 = worstAbove(trial_, bestWorst);
      if (w3 > bestWorst && edgesShortEnough(trial_, o.maxNewEdge)) {
        bestWorst = w3;
        best_.swap(trial_);
        found = lastByCollapse_ = true;
      }
    }
  if (fills_ < maxFills_ && (++fills_, delaunayFill(v, trial_))) {
    const double w3 = worstAbove(trial_, bestWorst);
    if (w3 > bestWorst && edgesShortEnough(trial_, o.maxNewEdge)) {
      bestWorst = w3;
      best_.swap(trial_);
      found = true;
      lastByCollapse_ = false;
    }
  }
  return found && beatsWorst(bestWorst, before, o.gain) && guardKept() && meanKept();
}

bool VertexRemoval::commit(std::vector<TetId>& created) {
  std::vector<TetId> made;
  if (!volume::replaceRegion(s_.mesh, star_, best_, &made)) return false;
  if (scores_)
    for (const TetId t : made) scores_->update(t);
  created.insert(created.end(), made.begin(), made.end());
  return true;
}

void VertexRemoval::refreshMean() {
  meanEta_ = sampledMeanEta(s_.mesh, [&](TetId t) { return score(t); });
}

bool VertexRemoval::tryRemove(VertexId v, const VertexRemovalOptions& o, std::vector<TetId>& created) {
  if (s_.isFixed(v)) return false;
  if (meanEta_ < 0) refreshMean();
  const VertexId one[1] = {v};
  if (!loadRegion(one, o.maxStar)) return false;
  double before = 1e300;
  std::size_t fixedIncidences = 0;
  for (const TetId t : star_) {
    before = std::min(before, score(t));
    for (int i = 0; i < 4; ++i) fixedIncidences += s_.isFixed(s_.mesh.vertex(t, i)) ? 1 : 0;
  }
  if (!(before < o.candidateBelow * o.candidateBelow * o.candidateBelow)) return false;
  if (!(static_cast<double>(fixedIncidences) >= o.heldShare * 3.0 * static_cast<double>(star_.size()))) return false;
  // v with its few free neighbours first: a crowded group whose points go only together
  // (removed one at a time, the mean drops on the way, or the last one's link is
  // cospherical and its Delaunay fill misses link faces); then v alone
  std::vector<VertexId> group = {v};
  for (const VertexId w : link_)
    if (!s_.isFixed(w)) group.push_back(w);
  if (group.size() >= 2 && group.size() <= o.maxGroup + 1) {
    if (loadRegion(group, o.maxGroupTets) && retriangulate(v, o, false)) {
      lastCluster_ = true;
      removedNow_ = group.size();
      return commit(created);
    }
    if (!loadRegion(one, o.maxStar)) return false;
  }
  lastCluster_ = false;
  removedNow_ = 1;
  return retriangulate(v, o, true) && commit(created);
}

VertexRemovalStats VertexRemoval::run(const VertexRemovalOptions& o, std::vector<TetId>& created) {
  VertexRemovalStats st;
  const double key = o.candidateBelow * o.candidateBelow * o.candidateBelow;
  refreshMean();
  fills_ = 0;
  maxFills_ = std::max(o.minFills, s_.mesh.numTets() / o.tetsPerFill);
  const std::size_t maxCandidates = std::max(o.minCandidates, s_.mesh.numTets() / o.tetsPerCandidate);
  // round 0: the candidates from one scan of the tets (the star's worst score and held
  // share per free vertex, as tryRemove tests them), worst first
  std::vector<std::pair<double, std::uint32_t>> order;
  {
    std::vector<double> worst(s_.mesh.numVertices(), 1e300);
    std::vector<std::uint32_t> incidences(s_.mesh.numVertices(), 0), fixedIncidences(s_.mesh.numVertices(), 0);
    for (std::uint32_t k = 0; k < s_.mesh.tetSlots(); ++k) {
      const TetId t(k);
      if (!s_.mesh.isAlive(t)) continue;
      const std::uint32_t* tv = s_.mesh.tetVertices(t);
      std::uint32_t fixed = 0;
      for (int i = 0; i < 4; ++i) fixed += s_.isFixed(VertexId(tv[i])) ? 1 : 0;
      const double sc = score(t);
      for (int i = 0; i < 4; ++i) {
        if (s_.isFixed(VertexId(tv[i]))) continue;
        incidences[tv[i]] += 3;
        fixedIncidences[tv[i]] += fixed;
        worst[tv[i]] = std::min(worst[tv[i]], sc);
      }
    }
    for (std::uint32_t v = 0; v < worst.size(); ++v)
      if (worst[v] < key && fixedIncidences[v] >= o.heldShare * incidences[v]) order.emplace_back(worst[v], v);
    std::sort(order.begin(), order.end());
  }
  // later rounds: the free vertices of the tets the previous round created, by id
  std::size_t roundStart = created.size();
  for (int round = 0; round < o.maxRounds && !order.empty(); ++round) {
    std::size_t removed = 0;
    for (const auto& [w, v] : order) {
      if (st.candidates >= maxCandidates) break;
      ++st.candidates;
      if (!tryRemove(VertexId(v), o, created)) continue;
      removed += removedNow_;
      ++(lastCluster_ ? st.byGroup : lastByCollapse_ ? st.byCollapse : st.byDelaunay);
    }
    st.removed += removed;
    order.clear();
    for (std::size_t k = roundStart; k < created.size(); ++k) {
      if (!s_.mesh.isAlive(created[k])) continue;
      const std::uint32_t* tv = s_.mesh.tetVertices(created[k]);
      for (int i = 0; i < 4; ++i)
        if (!s_.isFixed(VertexId(tv[i]))) order.emplace_back(0.0, tv[i]);
    }
    std::sort(order.begin(), order.end());
    order.erase(std::unique(order.begin(), order.end()), order.end());
    roundStart = created.size();
  }
  created.erase(std::remove_if(created.begin(), created.end(), [&](TetId t) { return !s_.mesh.isAlive(t); }),
                created.end());
  return st;
}

}  // namespace aniso::improve3d
