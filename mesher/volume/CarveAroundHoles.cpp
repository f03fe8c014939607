#include "mesher/volume/CarveAroundHoles.h"

#include <algorithm>
#include <set>

#include <Eigen/Geometry>

#include "mesher/delaunay3d/RemoveTets.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/volume/MeshQueries.h"
#include "mesher/volume/RayParity.h"
#include "mesher/volume/TetQuality.h"

namespace aniso {

using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

namespace {

constexpr std::int8_t kUnknown = -1, kOutside = 0, kInside = 1;

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

/// Signed volume enclosed by the outward boundary triangles (embedded ones excluded).
double enclosedVolume(const TetMesh& m, const SolidBoundary& boundary) {
  if (boundary.triangles.empty()) return 0;
  const Vec3 o = m.point(boundary.triangles.front()[0]);  // near the solid: less cancellation
  double v = 0;
  for (std::size_t t = 0; t < boundary.embeddedFrom && t < boundary.triangles.size(); ++t) {
    const auto& tri = boundary.triangles[t];
    v += (m.point(tri[0]) - o).dot((m.point(tri[1]) - o).cross(m.point(tri[2]) - o));
  }
  return v / 6.0;
}

/// The tets reachable from `seeds` across faces between two tets that `keep` accepts
/// (the seeds are accepted), marked per tet slot.
template <class Keep>
std::vector<std::uint8_t> reachable(const TetMesh& m, const std::vector<TetId>& seeds, Keep keep) {
  std::vector<std::uint8_t> reached(m.tetSlots(), 0);
  std::vector<TetId> queue;
  for (const TetId t : seeds)
    if (!reached[t.index]) {
      reached[t.index] = 1;
      queue.push_back(t);
    }
  for (std::size_t q = 0; q < queue.size(); ++q)
    for (int i = 0; i < 4; ++i)
      if (const TetId n = m.neighbour(queue[q], i); n.valid() && !reached[n.index] && keep(n)) {
        reached[n.index] = 1;
        queue.push_back(n);
      }
  return reached;
}

}  // namespace

HoleCarving carveAroundHoles(SolidTetMesh& s, const SolidBoundary& boundary, const del3d::EnclosingBox& box) {
  TetMesh& m = s.mesh;
  HoleCarving out;
  out.enclosedVolume = enclosedVolume(m, boundary);
  const std::string solid = "solid " + std::to_string(s.solid + 1);
  std::vector<TetId> star;
  const std::size_t nt = m.tetSlots();
  // (tet, face) -> boundary triangle, on both tets of each present triangle
  std::vector<int> faceTriangle(4 * nt, -1);
  std::vector<volume::FaceHandle> where(boundary.triangles.size());
  for (std::size_t t = 0; t < boundary.triangles.size(); ++t) {
    const auto& tri = boundary.triangles[t];
    const volume::FaceHandle h = volume::findFace(m, tri[0], tri[1], tri[2], star);
    where[t] = h;
    if (!h.valid()) {
      if (boundary.isEmbedded(t)) {
        out.problems.push_back(solid + ": a triangle of embedded face " + std::to_string(boundary.triangleFace[t] + 1) +
                               " is not a face of the tetrahedra");
        return out;
      }
      out.missing.push_back(t);
      continue;
    }
    faceTriangle[4 * std::size_t{h.tet.index} + h.face] = static_cast<int>(t);
    if (const TetId n = m.neighbour(h.tet, h.face); n.valid())
      for (int j = 0; j < 4; ++j)
        if (m.neighbour(n, j) == h.tet) faceTriangle[4 * std::size_t{n.index} + j] = static_cast<int>(t);
  }
  out.notFound = out.missing.size();
  // First the sides of the present boundary triangles (a tet with votes both ways is left
  // to the rays), then the hull and the box: outside.
  std::vector<std::int8_t> side(nt, kUnknown);
  std::vector<std::uint8_t> votes(nt, 0);  // bit 0: inside, bit 1: outside
  for (std::uint32_t k = 0; k < nt; ++k) {
    const TetId t(k);
    if (!m.isAlive(t)) continue;
    for (int i = 0; i < 4; ++i) {
      const int tri = faceTriangle[4 * std::size_t{k} + i];
      if (tri < 0 || boundary.isEmbedded(static_cast<std::size_t>(tri))) continue;
      const auto& v = boundary.triangles[static_cast<std::size_t>(tri)];
      const double o = predicates::orient3d(m.coords(v[0]), m.coords(v[1]), m.coords(v[2]), m.coords(m.vertex(t, i)));
      votes[k] |= o < 0 ? 1 : 2;
    }
    if (votes[k] == 1) side[k] = kInside;
    if (votes[k] == 2) side[k] = kOutside;
    for (int i = 0; i < 4; ++i) {
      const VertexId v = m.vertex(t, i);
      if (!m.neighbour(t, i).valid() || std::find(box.corners.begin(), box.corners.end(), v) != box.corners.end())
        side[k] = kOutside;
    }
  }
  // The others by the parity of a ray against the whole boundary (closed, the missing
  // triangles too); where every ray is degenerate, by the fronts below.
  {
    std::vector<Vec3> points(m.numVertices());
    for (std::uint32_t v = 0; v < m.numVertices(); ++v) points[v] = m.point(VertexId(v));
    std::vector<std::array<int, 3>> surface;
    for (std::size_t t = 0; t < boundary.embeddedFrom && t < boundary.triangles.size(); ++t) {
      const auto& tri = boundary.triangles[t];
      surface.push_back({static_cast<int>(tri[0].index), static_cast<int>(tri[1].index), static_cast<int>(tri[2].index)});
    }
    const RayParity parity(points, std::move(surface));
    for (std::uint32_t k = 0; k < nt; ++k) {
      const TetId t(k);
      if (!m.isAlive(t) || side[k] != kUnknown) continue;
      const Vec3 c = 0.25 * (m.point(m.vertex(t, 0)) + m.point(m.vertex(t, 1)) + m.point(m.vertex(t, 2)) +
                             m.point(m.vertex(t, 3)));
      if (const std::optional<bool> in = parity.inside(c)) side[k] = *in ? kInside : kOutside;
    }
  }
  // The fronts: breadth-first from every tet classified, across faces that are no present
  // boundary triangle (and across embedded ones: the solid on both sides).
  std::vector<TetId> queue;
  for (std::uint32_t k = 0; k < nt; ++k)
    if (m.isAlive(TetId(k)) && side[k] != kUnknown) queue.push_back(TetId(k));
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const TetId t = queue[q];
    for (int i = 0; i < 4; ++i) {
      const TetId n = m.neighbour(t, i);
      if (!n.valid() || side[n.index] != kUnknown) continue;
      const int tri = faceTriangle[4 * std::size_t{t.index} + i];
      if (tri >= 0 && !boundary.isEmbedded(static_cast<std::size_t>(tri))) continue;
      side[n.index] = side[t.index];
      queue.push_back(n);
    }
  }
  // Inside tets joined by their faces: a group on no present boundary triangle floats in
  // a hole (the fronts' leftovers, often flat): outside.
  {
    const auto inside = [&side](TetId t) { return side[t.index] == kInside; };
    std::vector<TetId> seeds;
    for (std::size_t t = 0; t < boundary.embeddedFrom && t < boundary.triangles.size(); ++t)
      if (const volume::FaceHandle& h = where[t]; h.valid())
        for (const TetId x : {h.tet, m.neighbour(h.tet, h.face)})
          if (x.valid() && inside(x)) seeds.push_back(x);
    const std::vector<std::uint8_t> anchored = reachable(m, seeds, inside);
    for (std::uint32_t k = 0; k < nt; ++k)
      if (side[k] == kInside && !anchored[k]) side[k] = kOutside;
  }
  // A present triangle must now separate an inside tet (on its inner side) from an
  // outside one; otherwise it is missing too.
  std::vector<std::uint8_t> lost(boundary.triangles.size(), 0);
  for (std::size_t t = 0; t < boundary.embeddedFrom && t < boundary.triangles.size(); ++t) {
    const volume::FaceHandle& h = where[t];
    if (!h.valid()) continue;
    const TetId n = m.neighbour(h.tet, h.face);
    const auto& v = boundary.triangles[t];
    const bool innerIsH =
        predicates::orient3d(m.coords(v[0]), m.coords(v[1]), m.coords(v[2]), m.coords(m.vertex(h.tet, h.face))) < 0;
    const TetId inner = innerIsH ? h.tet : n, outer = innerIsH ? n : h.tet;
    const bool ok = inner.valid() && side[inner.index] == kInside && (!outer.valid() || side[outer.index] != kInside);
    if (!ok) {
      lost[t] = 1;
      out.missing.push_back(t);
    }
  }
  std::sort(out.missing.begin(), out.missing.end());
  for (const std::size_t t : out.missing) {
    const auto& v = boundary.triangles[t];
    out.missingArea += triangleArea(m.point(v[0]), m.point(v[1]), m.point(v[2]));
  }
  std::vector<TetId> remove;
  for (std::uint32_t k = 0; k < nt; ++k)
    if (m.isAlive(TetId(k)) && side[k] != kInside) remove.push_back(TetId(k));
  if (remove.size() == m.numTets()) {
    out.problems.push_back(solid + ": no tetrahedron is inside");
    return out;
  }
  // Constrained bits: present triangles kept; none elsewhere (recovery marked every
  // present face; the lost ones are cleared).
  for (std::size_t t = 0; t < boundary.triangles.size(); ++t) {
    const volume::FaceHandle& h = where[t];
    if (!h.valid()) continue;
    const bool on = lost[t] == 0;
    m.setConstrained(h.tet, h.face, on);
  }
  del3d::removeTets(m, remove);
  // Patch faces: the hull faces left that are no boundary triangle.
  s.pinned.assign(m.numVertices(), 0);
  s.patchFaces.clear();
  for (std::uint32_t k = 0; k < nt; ++k) {
    const TetId t(k);
    if (!m.isAlive(t)) continue;
    for (int i = 0; i < 4; ++i) {
      if (m.neighbour(t, i).valid()) continue;
      const int tri = faceTriangle[4 * std::size_t{k} + i];
      if (tri >= 0 && !lost[static_cast<std::size_t>(tri)]) continue;
      if (!m.isConstrained(t, i)) m.setConstrained(t, i, true);
      std::array<std::uint32_t, 3> key;
      for (int j = 0; j < 3; ++j) {
        key[j] = m.vertex(t, del3d::kFaceVertex[i][j]).index;
        s.pinned[key[j]] = 1;
      }
      out.patchArea += triangleArea(m.point(VertexId(key[0])), m.point(VertexId(key[1])), m.point(VertexId(key[2])));
      std::sort(key.begin(), key.end());
      s.patchFaces.push_back(key);
    }
  }
  out.patchFaces = s.patchFaces.size();
  for (std::uint32_t k = 0; k < nt; ++k) {
    const TetId t(k);
    if (!m.isAlive(t)) continue;
    const Vec3 a = m.point(m.vertex(t, 0));
    out.keptVolume +=
        (m.point(m.vertex(t, 1)) - a).dot((m.point(m.vertex(t, 2)) - a).cross(m.point(m.vertex(t, 3)) - a)) / 6.0;
  }
  return out;
}

std::size_t peelPatchSlivers(SolidTetMesh& s, double angle, double maxVolume) {
  TetMesh& m = s.mesh;
  using Key = std::array<std::uint32_t, 3>;
  auto keyOf = [&m](TetId t, int i) {
    Key k;
    for (int j = 0; j < 3; ++j) k[j] = m.vertex(t, del3d::kFaceVertex[i][j]).index;
    std::sort(k.begin(), k.end());
    return k;
  };
  std::set<Key> patch(s.patchFaces.begin(), s.patchFaces.end());
  std::size_t removed = 0;
  double volume = 0;
  // bounded: every pass removes tets or stops; a tet is removed once
  for (std::size_t pass = 0; pass < m.tetSlots(); ++pass) {
    std::vector<TetId> peel;
    for (std::uint32_t k = 0; k < m.tetSlots(); ++k) {
      const TetId t(k);
      if (!m.isAlive(t)) continue;
      bool onPatch = false;
      for (int i = 0; i < 4 && !onPatch; ++i) onPatch = !m.neighbour(t, i).valid() && patch.count(keyOf(t, i));
      if (!onPatch) continue;
      const Vec3 a = m.point(m.vertex(t, 0)), b = m.point(m.vertex(t, 1)), c = m.point(m.vertex(t, 2)),
                 d = m.point(m.vertex(t, 3));
      // flat by its angles, or by its volume (nearly coincident vertices give angles of
      // no meaning, and a volume a reader's sum may find negative)
      if (tetMinDihedral(a, b, c, d) >= angle && tetMeanRatio(a, b, c, d) >= kPatchFlatRatio) continue;
      const double v = (b - a).dot((c - a).cross(d - a)) / 6.0;
      if (volume + v > maxVolume) continue;
      volume += v;
      peel.push_back(t);
    }
    if (peel.empty()) break;
    // the faces the peeled tets leave: patch faces now (or gone, between two peeled tets)
    std::vector<std::pair<TetId, int>> exposed;
    for (const TetId t : peel) {
      for (int i = 0; i < 4; ++i) {
        const TetId n = m.neighbour(t, i);
        if (!n.valid()) {
          patch.erase(keyOf(t, i));  // a boundary triangle's key is in no patch: nothing
          continue;
        }
        for (int j = 0; j < 4; ++j)
          if (m.neighbour(n, j) == t) exposed.emplace_back(n, j);
      }
    }
    del3d::removeTets(m, peel);
    removed += peel.size();
    for (const auto& [n, j] : exposed) {
      if (!m.isAlive(n) || m.neighbour(n, j).valid()) continue;
      if (!m.isConstrained(n, j)) m.setConstrained(n, j, true);
      const Key k = keyOf(n, j);
      patch.insert(k);
      if (s.pinned.size() < m.numVertices()) s.pinned.resize(m.numVertices(), 0);
      for (const std::uint32_t v : k) s.pinned[v] = 1;
    }
  }
  // tets that peeling cut off from every boundary triangle float in a hole: removed
  std::vector<TetId> seeds;  // the tets on a boundary triangle: a hull face no patch
  for (std::uint32_t k = 0; k < m.tetSlots(); ++k) {
    const TetId t(k);
    if (!m.isAlive(t)) continue;
    bool onBoundary = false;
    for (int i = 0; i < 4 && !onBoundary; ++i) onBoundary = !m.neighbour(t, i).valid() && !patch.count(keyOf(t, i));
    if (onBoundary) seeds.push_back(t);
  }
  const std::vector<std::uint8_t> anchored = reachable(m, seeds, [](TetId) { return true; });
  std::vector<TetId> floating;
  for (std::uint32_t k = 0; k < m.tetSlots(); ++k)
    if (m.isAlive(TetId(k)) && !anchored[k]) floating.push_back(TetId(k));
  if (!floating.empty()) {
    for (const TetId t : floating)
      for (int i = 0; i < 4; ++i) patch.erase(keyOf(t, i));
    del3d::removeTets(m, floating);
    removed += floating.size();
  }
  s.patchFaces.assign(patch.begin(), patch.end());
  return removed;
}

}  // namespace aniso
