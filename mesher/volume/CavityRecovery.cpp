#include "mesher/volume/CavityRecovery.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <unordered_set>

#include <Eigen/Geometry>

#include "mesher/delaunay3d/EdgeRing.h"
#include "mesher/delaunay3d/Inserter.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/volume/MeshQueries.h"
#include "mesher/volume/Pipe.h"
#include "mesher/volume/RegionReplace.h"

namespace aniso::volume {

using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

namespace {

/// VICINITY points of a patch no star recovers: this far inside (in mean edge lengths),
/// one depth per attempt.
constexpr double kVicinityOffsets[] = {0.3, 0.15, 0.5, 0.08, 0.22, 0.4};
/// Growth steps of a cavity side that has no star.
constexpr int kMaxLayers = 8;
/// Margin (in mean edge lengths) of the point a side grows towards.
constexpr double kGrowthMargin = 1e-3;
/// Growths of the patch when its two sides meet at a pinched rim.
constexpr int kMaxGrowth = 2;
/// Relative tolerance of the volume balance check of a retriangulation.
constexpr double kVolumeTolerance = 1e-9;

using Tri = CavityFace;

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) { return cavityEdgeKey(a, b); }

double vol6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return (b - a).dot((c - a).cross(d - a)); }

/// A constrained face strictly inside the cavity that is not a triangle of the patch
/// would be lost by the change.
bool losesConstrainedFace(const TetMesh& m, const Cavity& c, const std::vector<Tri>& tris,
                          const std::vector<int>& patch) {
  std::set<std::array<std::uint32_t, 3>> patchKeys;
  for (const int t : patch) {
    std::array<std::uint32_t, 3> k = {tris[t][0].index, tris[t][1].index, tris[t][2].index};
    std::sort(k.begin(), k.end());
    patchKeys.insert(k);
  }
  for (const TetId t : c.tets)
    for (int i = 0; i < 4; ++i) {
      const TetId n = m.neighbour(t, i);
      if (!n.valid() || !c.in.count(n.index) || !m.isConstrained(t, i)) continue;
      std::array<std::uint32_t, 3> k;
      for (int j = 0; j < 3; ++j) k[j] = m.vertex(t, del3d::kFaceVertex[i][j]).index;
      std::sort(k.begin(), k.end());
      if (!patchKeys.count(k)) return true;
    }
  return false;
}

}  // namespace

CavityRecovery::CavityRecovery(BoundaryTriangulation& bt) : bt_(bt) {
  const auto& tris = bt_.boundary.triangles;
  vertexTriangles_.resize(bt_.tets.mesh.numVertices());
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      edgeTriangles_[edgeKey(tris[t][k].index, tris[t][(k + 1) % 3].index)].push_back(static_cast<int>(t));
      vertexTriangles_[tris[t][k].index].push_back(static_cast<int>(t));
    }
}

bool CavityRecovery::triangleMissing(int t) {
  const Tri& tri = bt_.boundary.triangles[t];
  return !findFace(bt_.tets.mesh, tri[0], tri[1], tri[2], star_).valid();
}

int CavityRecovery::recoverTriangle(int f) {
  if (!triangleMissing(f)) return 0;
  return recoverPatch({f});
}

int CavityRecovery::recoverEdge(int e) {
  const auto& ed = bt_.boundary.edges[e];
  if (findEdge(bt_.tets.mesh, ed[0], ed[1], star_).valid()) return 0;
  const auto it = edgeTriangles_.find(edgeKey(ed[0].index, ed[1].index));
  if (it == edgeTriangles_.end()) return 0;
  return recoverPatch(it->second);
}

int CavityRecovery::recoverPatch(std::vector<int> seeds) {
  ++attempts_;
  TetMesh& m = bt_.tets.mesh;
  const auto& tris = bt_.boundary.triangles;
  // 1. The patch I of missing triangles.
  std::vector<int> patch;
  std::set<int> inPatch;
  for (const int s : seeds)
    if (inPatch.insert(s).second && triangleMissing(s)) patch.push_back(s);
  for (std::size_t k = 0; k < patch.size() && patch.size() < kMaxPatch; ++k) {
    const Tri& t = tris[patch[k]];
    for (int j = 0; j < 3; ++j) {
      if (findEdge(m, t[j], t[(j + 1) % 3], star_).valid()) continue;  // a present edge can be rim
      for (const int u : edgeTriangles_[edgeKey(t[j].index, t[(j + 1) % 3].index)]) {
        if (patch.size() >= kMaxPatch) break;
        if (inPatch.insert(u).second && triangleMissing(u)) patch.push_back(u);
      }
    }
  }
  if (patch.empty()) return 0;
  if (std::all_of(patch.begin(), patch.end(), [&](int t) { return failedThisRound_.count(t) > 0; }))
    return insertVicinityPoint(patch);
  const auto failed = [&] {
    failedThisRound_.insert(patch.begin(), patch.end());
    return insertVicinityPoint(patch);
  };
  for (int growth = 0;; ++growth) {
    const int r = retriangulate(patch);
    if (r >= 0) {
      ++successes_;
      return r;
    }
    if (r != kCavitySidesMixed || growth == kMaxGrowth) return failed();
    // The two sides meet where the rim pinches (at a vertex): take in every boundary
    // triangle around the patch's vertices, so that those vertices are inside I.
    std::set<std::uint32_t> vs;
    for (const int t : patch)
      for (const VertexId v : tris[t]) vs.insert(v.index);
    for (const std::uint32_t v : vs)
      for (const int u : vertexTriangles_[v])
        if (inPatch.insert(u).second) patch.push_back(u);
    if (patch.size() > 2 * kMaxPatch) return failed();
  }
}

int CavityRecovery::insertVicinityPoint(const std::vector<int>& patch) {
  TetMesh& m = bt_.tets.mesh;
  const auto& tris = bt_.boundary.triangles;
  PatchFrame frame;
  if (!patchFrame(m, tris, patch, frame)) return 0;
  const Vec3 normal = frame.normal, centroid = frame.centroid;
  const double h = frame.h;
  // Each new attempt on the same patch goes elsewhere: towards one of its triangles, at
  // another depth.
  const int attempt = vicinityAttempts_[*std::min_element(patch.begin(), patch.end())]++;
  const auto& tri = tris[patch[static_cast<std::size_t>(attempt) % patch.size()]];
  const Vec3 towards = (m.point(tri[0]) + m.point(tri[1]) + m.point(tri[2])) / 3.0;
  const double depth = kVicinityOffsets[attempt % std::size(kVicinityOffsets)];
  const Vec3 p = 0.5 * (centroid + towards) - depth * h * normal;
  vertexStar(m, tris[patch.front()][0], star_);
  if (star_.empty()) return 0;
  del3d::Inserter inserter(m);
  const del3d::InsertResult r = inserter.insert(p, star_.front());
  bt_.tets.node.resize(m.numVertices(), -1);
  return r.status == del3d::InsertStatus::Inserted ? 1 : 0;
}

int CavityRecovery::retriangulate(const std::vector<int>& patch) {
  TetMesh& m = bt_.tets.mesh;
  const auto& tris = bt_.boundary.triangles;
  const PatchEdges edges = patchEdges(tris, patch);
  // 2. The cavity C.
  Cavity cavity;
  if (collectCavity(m, tris, patch, edges, cavity) != 0) return kCavityFailed;
  PatchFrame frame;
  if (!patchFrame(m, tris, patch, frame)) return kCavityFailed;
  // 3-4. The two sides and their stars; a side without one grows and both are tried again.
  // An apex on a triangle of I would flatten it: those vertices are excluded.
  std::set<std::uint32_t> patchVertices;
  for (const int t : patch)
    for (const VertexId v : tris[t]) patchVertices.insert(v.index);
  CavitySides sides;
  Apex in, out;
  for (int layer = 0;; ++layer) {
    sides = splitSides(m, cavity, edges, tris);
    if (sides.status != 0) return sides.status;
    for (const int t : patch) {
      sides.inner.push_back({tris[t][0], tris[t][2], tris[t][1]});
      sides.outer.push_back(tris[t]);
    }
    in = chooseApex(m, sides.inner, apexCandidates(m, sides.inner, cavity.tets, frame, -1.0), patchVertices);
    out = chooseApex(m, sides.outer, apexCandidates(m, sides.outer, cavity.tets, frame, 1.0), patchVertices);
    if (in.found && out.found) break;
    if (layer == kMaxLayers) return kCavityFailed;
    const double margin = kGrowthMargin * frame.h;
    if (!in.found)
      growSide(m, sides.inner, sides.innerNext, edges, frame.centroid - 0.25 * frame.h * frame.normal, margin, cavity);
    if (!out.found)
      growSide(m, sides.outer, sides.outerNext, edges, frame.centroid + 0.25 * frame.h * frame.normal, margin, cavity);
  }
  // 5. Checks, then the change.
  if (losesConstrainedFace(m, cavity, tris, patch)) return kCavityFailed;
  return replaceByStars(cavity, sides, in, out, patch);
}

int CavityRecovery::replaceByStars(const Cavity& cavity, const CavitySides& sides, const Apex& in, const Apex& out,
                                   const std::vector<int>& patch) {
  TetMesh& m = bt_.tets.mesh;
  const auto& tris = bt_.boundary.triangles;
  double oldVolume = 0;
  std::set<std::uint32_t> oldFixed;
  for (const TetId t : cavity.tets) {
    oldVolume += vol6(m.point(m.vertex(t, 0)), m.point(m.vertex(t, 1)), m.point(m.vertex(t, 2)), m.point(m.vertex(t, 3)));
    for (int k = 0; k < 4; ++k)
      if (bt_.tets.isFixed(m.vertex(t, k))) oldFixed.insert(m.vertex(t, k).index);
  }
  std::vector<std::array<VertexId, 4>> quads;
  double newVolume = 0;
  auto star = [&](const std::vector<Tri>& surface, VertexId apex, const Vec3& p) {
    for (const Tri& f : surface) {
      if (f[0] == apex || f[1] == apex || f[2] == apex) continue;
      quads.push_back({f[0], f[1], f[2], apex});
      newVolume += vol6(m.point(f[0]), m.point(f[1]), m.point(f[2]), p);
    }
  };
  // New apexes are added only once the stars are known to fit (no vertex left behind).
  star(sides.inner, in.isNew ? VertexId() : in.vertex, in.p);
  const std::size_t innerQuads = quads.size();
  star(sides.outer, out.isNew ? VertexId() : out.vertex, out.p);
  for (const auto& q : quads)
    for (const VertexId v : q) oldFixed.erase(v.index);
  if (!oldFixed.empty() || std::fabs(newVolume - oldVolume) > kVolumeTolerance * std::fabs(oldVolume))
    return kCavityFailed;
  const VertexId pin = in.isNew ? bt_.tets.addFreeVertex(in.p) : in.vertex;
  const VertexId pout = out.isNew ? bt_.tets.addFreeVertex(out.p) : out.vertex;
  for (std::size_t k = 0; k < quads.size(); ++k)
    if (!quads[k][3].valid()) quads[k][3] = k < innerQuads ? pin : pout;
  if (!replaceRegion(m, cavity.tets, quads)) return kCavityFailed;
  for (const int t : patch) {
    const FaceHandle fh = findFace(m, tris[t][0], tris[t][1], tris[t][2], star_);
    if (fh.valid()) m.setConstrained(fh.tet, fh.face, true);
  }
  return (in.isNew ? 1 : 0) + (out.isNew ? 1 : 0);
}

}  // namespace aniso::volume
