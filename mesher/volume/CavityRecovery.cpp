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

/// A star is taken from an existing vertex without looking further when its worst tet has
/// at least this shape measure (volume / longest edge^3; 0.118 for the regular tet).
constexpr double kGoodVertexStar = 0.01;
/// Offsets of the candidate new points from the patch, in units of its mean edge length.
constexpr double kOffsets[] = {0.1, 0.25, 0.5, 1.0, 0.05};
/// Margins (in units of the patch's mean edge length) of the kernel points sought.
constexpr double kKernelMargins[] = {0.05, 0.01, 1e-3, 1e-5, 1e-7};
/// VICINITY points of a patch no star recovers: this far inside (in mean edge lengths),
/// one depth per attempt.
constexpr double kVicinityOffsets[] = {0.3, 0.15, 0.5, 0.08, 0.22, 0.4};
/// Growth steps of a cavity side that has no star.
constexpr int kMaxLayers = 8;
/// Margin (in mean edge lengths) of the point a side grows towards.
constexpr double kGrowthMargin = 1e-3;
/// Growths of the patch when its two sides meet at a pinched rim.
constexpr int kMaxGrowth = 2;
/// retriangulate(): the patch's rim does not separate the two sides; other failures.
constexpr int kSidesMixed = -2;
constexpr int kFailed = -1;
/// Relative tolerance of the volume balance check of a retriangulation.
constexpr double kVolumeTolerance = 1e-9;

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

using Tri = std::array<VertexId, 3>;

Vec3 point(const TetMesh& m, VertexId v) { return m.point(v); }

double vol6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return (b - a).dot((c - a).cross(d - a)); }

/// Worst shape of the star of `p` over `faces` (each oriented towards the inside):
/// negative when a tet is not positively oriented (exact test). Faces containing `skip`
/// (the apex when it is a vertex) are left out.
double starShape(const TetMesh& m, const std::vector<Tri>& faces, const double* p, VertexId skip) {
  double worst = 1e300;
  const Vec3 pv(p[0], p[1], p[2]);
  for (const Tri& f : faces) {
    if (f[0] == skip || f[1] == skip || f[2] == skip) continue;
    if (predicates::orient3d(m.coords(f[0]), m.coords(f[1]), m.coords(f[2]), p) <= 0) return -1;
    const Vec3 a = point(m, f[0]), b = point(m, f[1]), c = point(m, f[2]);
    const double l = std::max({(a - b).norm(), (b - c).norm(), (c - a).norm(), (pv - a).norm(), (pv - b).norm(),
                               (pv - c).norm()});
    worst = std::min(worst, vol6(a, b, c, pv) / 6.0 / (l * l * l));
  }
  return worst;
}

/// A point strictly on the inner side of every face (the kernel of the polyhedron) by
/// cyclic relaxation (Agmon–Motzkin): from `start`, repeatedly push the point across the
/// most violated half-space to `margin` inside it. Returns false when the iterations do
/// not settle (the kernel may be empty or thinner than the margin); `out` is then the last
/// point reached.
bool relaxIntoKernel(const TetMesh& m, const std::vector<Tri>& faces, Vec3 start, double margin, Vec3& out) {
  constexpr int kIterations = 2000;
  std::vector<Vec3> normal(faces.size());
  std::vector<double> offset(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Vec3 a = m.point(faces[f][0]), b = m.point(faces[f][1]), c = m.point(faces[f][2]);
    Vec3 n = (b - a).cross(c - a);  // points into the polyhedron (faces are oriented so)
    const double len = n.norm();
    if (!(len > 0)) return false;
    normal[f] = n / len;
    offset[f] = normal[f].dot(a);
  }
  Vec3 p = start;
  for (int it = 0; it < kIterations; ++it) {
    double worst = margin;
    std::size_t wf = faces.size();
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const double d = normal[f].dot(p) - offset[f];
      if (d < worst) {
        worst = d;
        wf = f;
      }
    }
    if (wf == faces.size()) {
      out = p;
      return true;
    }
    p += (margin - worst) * normal[wf];
  }
  out = p;  // the best effort, for growing the polyhedron towards a star (see below)
  return false;
}

struct Apex {
  bool found = false;
  bool isNew = false;
  VertexId vertex;
  Vec3 p{0, 0, 0};
};

/// The apex of the best star over `faces`: an existing vertex of them (not in `forbidden`)
/// when one is good enough, else the best new point among `candidates`, else the best
/// vertex.
Apex chooseApex(const TetMesh& m, const std::vector<Tri>& faces, const std::vector<Vec3>& candidates,
                const std::set<std::uint32_t>& forbidden) {
  std::set<std::uint32_t> verts;
  for (const Tri& f : faces)
    for (const VertexId v : f)
      if (!forbidden.count(v.index)) verts.insert(v.index);
  Apex bestVertex;
  double bestVertexShape = 0;
  for (const std::uint32_t v : verts) {
    const double s = starShape(m, faces, m.coords(VertexId(v)), VertexId(v));
    if (s > bestVertexShape) {
      bestVertexShape = s;
      bestVertex = {true, false, VertexId(v), m.point(VertexId(v))};
    }
  }
  if (bestVertex.found && bestVertexShape >= kGoodVertexStar) return bestVertex;
  Apex bestNew;
  double bestNewShape = 0;
  for (const Vec3& c : candidates) {
    if (!c.allFinite()) continue;
    const double s = starShape(m, faces, c.data(), VertexId());
    if (s > bestNewShape) {
      bestNewShape = s;
      bestNew = {true, true, VertexId(), c};
    }
  }
  if (bestNew.found && bestNewShape > bestVertexShape) return bestNew;
  return bestVertex;
}

/// Where new points near a patch go: its unit outward normal (area-weighted), its
/// area-weighted centroid and its mean edge length. False for a patch of no area.
struct PatchFrame {
  Vec3 normal{0, 0, 0}, centroid{0, 0, 0};
  double h = 0;
};

bool patchFrame(const TetMesh& m, const std::vector<Tri>& tris, const std::vector<int>& patch, PatchFrame& out) {
  Vec3 normal(0, 0, 0), centroid(0, 0, 0);
  double area = 0, edgeSum = 0;
  for (const int t : patch) {
    const Vec3 a = m.point(tris[t][0]), b = m.point(tris[t][1]), c = m.point(tris[t][2]);
    const Vec3 n = (b - a).cross(c - a);
    normal += n;
    area += 0.5 * n.norm();
    centroid += 0.5 * n.norm() * (a + b + c) / 3.0;
    edgeSum += (a - b).norm() + (b - c).norm() + (c - a).norm();
  }
  if (!(area > 0) || !(normal.norm() > 0)) return false;
  out.normal = normal.normalized();
  out.centroid = centroid / area;
  out.h = edgeSum / (3.0 * static_cast<double>(patch.size()));
  return true;
}

/// Step 3: the boundary faces of the cavity (oriented into it) split by the rim of I into
/// the outer (+1) and inner (-1) side, with the tet across each face.
struct Sides {
  int status = 0;  ///< 0, kFailed or kSidesMixed
  std::vector<Tri> inner, outer;
  std::vector<TetId> innerNext, outerNext;  ///< tet across each face (for growing C)
};

Sides splitSides(const TetMesh& m, const std::vector<TetId>& cavity, const std::unordered_set<std::uint32_t>& inCavity,
                 const std::map<std::uint64_t, int>& patchEdgeUses, const std::map<std::uint64_t, int>& rimTriangle,
                 const std::vector<Tri>& tris) {
  Sides out;
  std::vector<Tri> faces;
  std::vector<TetId> next;
  for (const TetId t : cavity)
    for (int i = 0; i < 4; ++i) {
      const TetId n = m.neighbour(t, i);
      if (n.valid() && inCavity.count(n.index)) continue;
      if (!n.valid()) {  // the cavity reaches the hull: no room to work
        out.status = kFailed;
        return out;
      }
      const auto& fv = del3d::kFaceVertex[i];
      faces.push_back({m.vertex(t, fv[0]), m.vertex(t, fv[1]), m.vertex(t, fv[2])});
      next.push_back(m.isConstrained(t, i) ? TetId() : n);
    }
  std::vector<int> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto isRim = [&](std::uint64_t key) {
    const auto pe = patchEdgeUses.find(key);
    return pe != patchEdgeUses.end() && pe->second == 1;
  };
  std::map<std::uint64_t, std::vector<int>> faceEdges;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int j = 0; j < 3; ++j) faceEdges[edgeKey(faces[f][j].index, faces[f][(j + 1) % 3].index)].push_back(static_cast<int>(f));
  for (const auto& [key, list] : faceEdges) {
    if (isRim(key)) continue;  // a rim edge separates the sides
    for (std::size_t k = 1; k < list.size(); ++k) parent[find(list[k])] = find(list[0]);
  }
  // Side of each group from a face on a rim edge: +1 outer, -1 inner.
  std::map<int, int> side;
  for (const auto& [key, list] : faceEdges) {
    if (!isRim(key)) continue;
    const Tri& t = tris[rimTriangle.at(key)];
    for (const int f : list) {
      VertexId q;
      for (const VertexId v : faces[f])
        if ((key >> 32) != v.index && (key & 0xFFFFFFFFu) != v.index) q = v;
      const double o = predicates::orient3d(m.coords(t[0]), m.coords(t[1]), m.coords(t[2]), m.coords(q));
      if (o == 0) continue;
      const int s = o > 0 ? 1 : -1;
      auto [it, fresh] = side.emplace(find(f), s);
      if (!fresh && it->second != s) {  // a group on both sides: not separable here
        out.status = kSidesMixed;
        return out;
      }
    }
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto it = side.find(find(static_cast<int>(f)));
    if (it == side.end()) {  // a group touching no rim edge
      out.status = kFailed;
      return out;
    }
    (it->second > 0 ? out.outer : out.inner).push_back(faces[f]);
    (it->second > 0 ? out.outerNext : out.innerNext).push_back(next[f]);
  }
  return out;
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
  for (int growth = 0;; ++growth) {
    const int r = retriangulate(patch);
    if (r >= 0) {
      ++successes_;
      return r;
    }
    if (r != kSidesMixed || growth == kMaxGrowth) return insertVicinityPoint(patch);
    // The two sides meet where the rim pinches (at a vertex): take in every boundary
    // triangle around the patch's vertices, so that those vertices are inside I.
    std::set<std::uint32_t> vs;
    for (const int t : patch)
      for (const VertexId v : tris[t]) vs.insert(v.index);
    for (const std::uint32_t v : vs)
      for (const int u : vertexTriangles_[v])
        if (inPatch.insert(u).second) patch.push_back(u);
    if (patch.size() > 2 * kMaxPatch) return insertVicinityPoint(patch);
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
  // Edges of I: rim (one triangle of I) or inner.
  std::map<std::uint64_t, int> patchEdgeUses;
  std::map<std::uint64_t, int> rimTriangle;
  for (const int t : patch)
    for (int j = 0; j < 3; ++j) {
      const std::uint64_t k = edgeKey(tris[t][j].index, tris[t][(j + 1) % 3].index);
      ++patchEdgeUses[k];
      rimTriangle[k] = t;
    }
  // 2. The cavity C (with both sides of the triangles of I already present).
  std::unordered_set<std::uint32_t> inCavity;
  std::vector<TetId> cavity;
  auto add = [&](TetId t) {
    if (t.valid() && inCavity.insert(t.index).second) cavity.push_back(t);
  };
  for (const int t : patch) {
    const FaceHandle fh = findFace(m, tris[t][0], tris[t][1], tris[t][2], star_);
    if (!fh.valid()) continue;
    add(fh.tet);
    add(m.neighbour(fh.tet, fh.face));
  }
  Pipe pipe;
  del3d::EdgeRing ring;
  for (const int t : patch) {
    trianglePipe(m, tris[t][0], tris[t][1], tris[t][2], pipe);
    if (pipe.degenerate) return kFailed;
    for (const EdgeRef& e : pipe.edges) {
      del3d::edgeRing(m, e.tet, e.i, e.j, ring);
      for (const TetId u : ring.tets) add(u);
    }
  }
  for (const auto& [key, uses] : patchEdgeUses) {
    const VertexId a(static_cast<std::uint32_t>(key >> 32)), b(static_cast<std::uint32_t>(key & 0xFFFFFFFFu));
    const EdgeHandle present = findEdge(m, a, b, star_);
    if (present.valid()) {
      // An edge inside I that is present: every tet around it goes, so that no face of
      // C's boundary touches it (the two sides meet only at the rim).
      if (uses > 1) {
        del3d::edgeRing(m, present.tet, present.i, present.j, ring);
        for (const TetId u : ring.tets) add(u);
      }
      continue;
    }
    segmentPipe(m, a, b, pipe);
    if (pipe.degenerate) return kFailed;
    for (const FaceRef& f : pipe.faces) {
      add(f.tet);
      add(m.neighbour(f.tet, f.face));
    }
    for (const EdgeRef& e : pipe.edges) {
      del3d::edgeRing(m, e.tet, e.i, e.j, ring);
      for (const TetId u : ring.tets) add(u);
    }
  }
  if (cavity.empty()) return kFailed;
  // Outward patch normal, centroid and size: where the new points go.
  PatchFrame frame;
  if (!patchFrame(m, tris, patch, frame)) return kFailed;
  const Vec3 normal = frame.normal, centroid = frame.centroid;
  const double h = frame.h;
  auto candidates = [&](const std::vector<Tri>& surface, double direction) {
    std::vector<Vec3> c;
    for (const double s : kOffsets) c.push_back(centroid + direction * s * h * normal);
    Vec3 mean(0, 0, 0);
    std::set<std::uint32_t> vs;
    for (const Tri& f : surface)
      for (const VertexId v : f)
        if (vs.insert(v.index).second) mean += m.point(v);
    mean /= static_cast<double>(vs.size());
    c.push_back(mean);
    c.push_back(0.5 * (mean + centroid));
    for (const TetId t : cavity) {  // the centroids of the cavity's tets
      Vec3 g(0, 0, 0);
      for (int k = 0; k < 4; ++k) g += 0.25 * m.point(m.vertex(t, k));
      c.push_back(g);
    }
    for (const double margin : kKernelMargins) {  // a point of the kernel, when one is found
      Vec3 k;
      if (relaxIntoKernel(m, surface, centroid + direction * 0.25 * h * normal, margin * h, k)) c.push_back(k);
    }
    return c;
  };
  // 4. The two stars; a side without one takes in the next layer of tets (not across a
  // constrained face, not touching the rim) and both are tried again.
  // An apex on a triangle of I would flatten it: those vertices are excluded.
  std::set<std::uint32_t> patchVertices;
  for (const int t : patch)
    for (const VertexId v : tris[t]) patchVertices.insert(v.index);
  auto touchesRim = [&](TetId t) {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const auto pe = patchEdgeUses.find(edgeKey(m.vertex(t, i).index, m.vertex(t, j).index));
        if (pe != patchEdgeUses.end() && pe->second == 1) return true;
      }
    return false;
  };
  std::vector<Tri> inner, outer;
  Apex in, out;
  for (int layer = 0;; ++layer) {
    Sides sides = splitSides(m, cavity, inCavity, patchEdgeUses, rimTriangle, tris);
    if (sides.status != 0) return sides.status;
    inner = std::move(sides.inner);
    outer = std::move(sides.outer);
    for (const int t : patch) {
      inner.push_back({tris[t][0], tris[t][2], tris[t][1]});
      outer.push_back(tris[t]);
    }
    in = chooseApex(m, inner, candidates(inner, -1.0), patchVertices);
    out = chooseApex(m, outer, candidates(outer, 1.0), patchVertices);
    if (in.found && out.found) break;
    if (layer == kMaxLayers) return kFailed;
    // Grow each side without a star towards one: take in the tets beyond the faces that
    // a point near its kernel (best effort) does not see.
    auto grow = [&](const std::vector<Tri>& faces, const std::vector<TetId>& next, double direction) {
      Vec3 q;
      relaxIntoKernel(m, faces, centroid + direction * 0.25 * h * normal, kGrowthMargin * h, q);
      std::size_t added = 0;
      for (std::size_t f = 0; f < next.size(); ++f) {
        if (!next[f].valid() || touchesRim(next[f])) continue;
        if (predicates::orient3d(m.coords(faces[f][0]), m.coords(faces[f][1]), m.coords(faces[f][2]), q.data()) > 0)
          continue;
        add(next[f]);
        ++added;
      }
      if (added == 0)  // nothing hides the point: take the whole next layer
        for (const TetId n : next)
          if (n.valid() && !touchesRim(n)) add(n);
    };
    if (!in.found) grow(inner, sides.innerNext, -1.0);
    if (!out.found) grow(outer, sides.outerNext, 1.0);
  }
  // 5. Checks, then the change.
  double oldVolume = 0;
  std::set<std::uint32_t> oldFixed;
  for (const TetId t : cavity) {
    oldVolume += vol6(m.point(m.vertex(t, 0)), m.point(m.vertex(t, 1)), m.point(m.vertex(t, 2)), m.point(m.vertex(t, 3)));
    for (int k = 0; k < 4; ++k)
      if (bt_.tets.isFixed(m.vertex(t, k))) oldFixed.insert(m.vertex(t, k).index);
  }
  // A constrained face inside C would be lost: only the triangles of I may be there.
  std::set<std::array<std::uint32_t, 3>> patchKeys;
  for (const int t : patch) {
    std::array<std::uint32_t, 3> k = {tris[t][0].index, tris[t][1].index, tris[t][2].index};
    std::sort(k.begin(), k.end());
    patchKeys.insert(k);
  }
  for (const TetId t : cavity)
    for (int i = 0; i < 4; ++i) {
      const TetId n = m.neighbour(t, i);
      if (!n.valid() || !inCavity.count(n.index) || !m.isConstrained(t, i)) continue;
      std::array<std::uint32_t, 3> k;
      for (int j = 0; j < 3; ++j) k[j] = m.vertex(t, del3d::kFaceVertex[i][j]).index;
      std::sort(k.begin(), k.end());
      if (!patchKeys.count(k)) return kFailed;
    }
  const VertexId pin = in.isNew ? bt_.tets.addFreeVertex(in.p) : in.vertex;
  const VertexId pout = out.isNew ? bt_.tets.addFreeVertex(out.p) : out.vertex;
  std::vector<std::array<VertexId, 4>> quads;
  double newVolume = 0;
  auto star = [&](const std::vector<Tri>& surface, VertexId apex) {
    for (const Tri& f : surface) {
      if (f[0] == apex || f[1] == apex || f[2] == apex) continue;
      quads.push_back({f[0], f[1], f[2], apex});
      newVolume += vol6(m.point(f[0]), m.point(f[1]), m.point(f[2]), m.point(apex));
    }
  };
  star(inner, pin);
  star(outer, pout);
  for (const auto& q : quads)
    for (const VertexId v : q) oldFixed.erase(v.index);
  if (!oldFixed.empty() || std::fabs(newVolume - oldVolume) > kVolumeTolerance * std::fabs(oldVolume)) return kFailed;
  if (!replaceRegion(m, cavity, quads)) return kFailed;
  for (const int t : patch) {
    const FaceHandle fh = findFace(m, tris[t][0], tris[t][1], tris[t][2], star_);
    if (fh.valid()) m.setConstrained(fh.tet, fh.face, true);
  }
  return (in.isNew ? 1 : 0) + (out.isNew ? 1 : 0);
}

}  // namespace aniso::volume
