#include "mesher/volume/FoldRegion.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include <Eigen/Geometry>

#include "mesher/predicates/Predicates.h"

namespace aniso {
namespace {

using Tri = std::array<int, 3>;

/// Rings a region grows by when its boundary is not one simple flat loop.
constexpr int kMaxRings = 2;
/// Step 2: the largest distance of a loop node from the loop's plane, in loop extents.
constexpr double kMaxLoopBend = 0.05;
/// The same for a fan from a hub (step 4): the star of a node on a curved face, as the
/// surface mesher makes them (a cap of 0.25 extents: about 28 degrees of a sphere).
constexpr double kMaxHubBend = 0.25;

std::pair<int, int> key(int a, int b) { return std::minmax(a, b); }

/// Pocket triangles reached from `bad` (across the face's edges) turned away from `good`.
constexpr std::size_t kMaxPocket = 64;

Vec3 normalOf(const SurfaceMesh& m, const Tri& t) {
  return (m.nodes[t[1]] - m.nodes[t[0]]).cross(m.nodes[t[2]] - m.nodes[t[0]]);
}

/// Step 1, first form: the pocket turned away from `good`, reached from `bad`, plus good.
std::vector<int> pocket(const SurfaceMesh& m, const std::vector<Tri>& tris, int bad, int good) {
  const Vec3 ng = normalOf(m, tris[good]).normalized();
  auto away = [&](int t) {
    const Vec3 n = normalOf(m, tris[t]);
    return !(n.dot(ng) >= kFoldCosine * n.norm()) || !(n.norm() > 0);
  };
  std::map<std::pair<int, int>, std::vector<int>> uses;
  for (int t = 0; t < static_cast<int>(tris.size()); ++t)
    for (int k = 0; k < 3; ++k) uses[key(tris[t][k], tris[t][(k + 1) % 3])].push_back(t);
  std::vector<int> out = {bad};
  std::set<int> in = {bad, good};
  for (std::size_t k = 0; k < out.size() && out.size() < kMaxPocket; ++k)
    for (int j = 0; j < 3; ++j)
      for (const int u : uses[key(tris[out[k]][j], tris[out[k]][(j + 1) % 3])])
        if (!in.count(u) && away(u)) {
          in.insert(u);
          out.push_back(u);
        }
  out.push_back(good);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<int> ringAround(const std::vector<Tri>& tris, const std::vector<int>& seed) {
  std::set<int> verts;
  for (const int t : seed) verts.insert(tris[t].begin(), tris[t].end());
  std::vector<int> out;
  for (int t = 0; t < static_cast<int>(tris.size()); ++t)
    if (verts.count(tris[t][0]) || verts.count(tris[t][1]) || verts.count(tris[t][2])) out.push_back(t);
  return out;
}

bool boundaryLoop(const std::vector<Tri>& tris, const std::vector<int>& region, std::vector<int>& loop) {
  std::map<std::pair<int, int>, int> net;  // +1 per use a->b with a < b, -1 for b->a
  for (const int t : region)
    for (int k = 0; k < 3; ++k) {
      const int a = tris[t][k], b = tris[t][(k + 1) % 3];
      net[key(a, b)] += a < b ? 1 : -1;
    }
  std::map<int, int> next;
  std::size_t edges = 0;
  for (const auto& [e, n] : net) {
    if (n == 0) continue;
    if (n != 1 && n != -1) return false;
    if (!next.emplace(n > 0 ? e.first : e.second, n > 0 ? e.second : e.first).second) return false;
    ++edges;
  }
  if (edges < 3) return false;
  loop.clear();
  int v = next.begin()->first;
  for (std::size_t k = 0; k < edges; ++k) {
    loop.push_back(v);
    const auto it = next.find(v);
    if (it == next.end()) return false;
    v = it->second;
  }
  return v == loop.front() && std::set<int>(loop.begin(), loop.end()).size() == edges;
}

bool segmentsTouch(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = predicates::orient2d(a.data(), b.data(), c.data());
  const double o2 = predicates::orient2d(a.data(), b.data(), d.data());
  const double o3 = predicates::orient2d(c.data(), d.data(), a.data());
  const double o4 = predicates::orient2d(c.data(), d.data(), b.data());
  return !((o1 > 0 && o2 > 0) || (o1 < 0 && o2 < 0) || (o3 > 0 && o4 > 0) || (o3 < 0 && o4 < 0));
}

/// Ear clipping of a simple counter-clockwise polygon, the best-shaped ear first.
bool earClip(const std::vector<Vec2>& p, std::vector<Tri>& out) {
  const int n = static_cast<int>(p.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      if (segmentsTouch(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return false;
    }
  std::vector<int> poly(n);
  std::iota(poly.begin(), poly.end(), 0);
  out.clear();
  while (poly.size() >= 3) {
    const int m = static_cast<int>(poly.size());
    int best = -1;
    double bestShape = 0;
    for (int i = 0; i < m; ++i) {
      const int a = poly[(i + m - 1) % m], b = poly[i], c = poly[(i + 1) % m];
      if (!(predicates::orient2d(p[a].data(), p[b].data(), p[c].data()) > 0)) continue;
      bool empty = true;
      for (const int q : poly) {
        if (q == a || q == b || q == c) continue;
        if (predicates::orient2d(p[a].data(), p[b].data(), p[q].data()) >= 0 &&
            predicates::orient2d(p[b].data(), p[c].data(), p[q].data()) >= 0 &&
            predicates::orient2d(p[c].data(), p[a].data(), p[q].data()) >= 0) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      const Vec2 u = p[b] - p[a], v = p[c] - p[a];
      const double area = 0.5 * (u.x() * v.y() - u.y() * v.x());
      const double shape = area / (u.squaredNorm() + v.squaredNorm() + (p[c] - p[b]).squaredNorm());
      if (best < 0 || shape > bestShape) {
        best = i;
        bestShape = shape;
      }
    }
    if (best < 0) return false;
    out.push_back({poly[(best + m - 1) % m], poly[best], poly[(best + 1) % m]});
    poly.erase(poly.begin() + best);
  }
  return true;
}

/// The fan of a counter-clockwise polygon from a point inside it (index p.size() in the
/// triangles): false unless every edge sees the point on its left (star-shaped).
bool fanFrom(const std::vector<Vec2>& p, const Vec2& hub, std::vector<Tri>& out) {
  const int n = static_cast<int>(p.size());
  out.clear();
  for (int i = 0; i < n; ++i) {
    if (!(predicates::orient2d(p[i].data(), p[(i + 1) % n].data(), hub.data()) > 0)) return false;
    out.push_back({i, (i + 1) % n, n});
  }
  return true;
}

/// Steps 2-4 for one region.
bool replaceRegion(const SurfaceMesh& m, const std::vector<Tri>& tris, const std::vector<int>& region,
                   const std::vector<int>& useCount, const std::set<Tri>& existing, FoldRepair& out) {
  std::vector<int> loop;
  if (!boundaryLoop(tris, region, loop)) return false;
  const std::set<int> onLoop(loop.begin(), loop.end());
  std::map<int, int> uses;
  for (const int t : region)
    for (const int v : tris[t])
      if (!onLoop.count(v)) ++uses[v];
  int hub = -1;  // a CAD vertex or edge node inside the loop: kept, the loop fanned from it
  for (const auto& [v, n] : uses) {
    if (n != useCount[v]) return false;
    if (m.nodeOn[v].kind == NodeOn::Kind::Face) continue;
    if (hub >= 0) return false;
    hub = v;
  }
  Vec3 area(0, 0, 0), centroid(0, 0, 0);
  for (std::size_t k = 0; k < loop.size(); ++k) {
    area += m.nodes[loop[k]].cross(m.nodes[loop[(k + 1) % loop.size()]]);
    centroid += m.nodes[loop[k]] / static_cast<double>(loop.size());
  }
  if (!(area.norm() > 0)) return false;
  const Vec3 n = area.normalized();
  const Vec3 u = n.unitOrthogonal(), w = n.cross(u);
  std::vector<Vec2> p;
  double extent = 0, bend = 0;
  for (const int v : loop) {
    extent = std::max(extent, (m.nodes[v] - centroid).norm());
    bend = std::max(bend, std::abs(n.dot(m.nodes[v] - centroid)));
    p.emplace_back(m.nodes[v].dot(u), m.nodes[v].dot(w));
  }
  for (const int t : region)  // the dropped nodes too: the region is replaced, not reshaped
    for (const int v : tris[t]) bend = std::max(bend, std::abs(n.dot(m.nodes[v] - centroid)));
  if (!(bend <= (hub < 0 ? kMaxLoopBend : kMaxHubBend) * extent)) return false;
  std::vector<Tri> ears;
  if (hub < 0) {
    if (!earClip(p, ears)) return false;
  } else if (!fanFrom(p, Vec2(m.nodes[hub].dot(u), m.nodes[hub].dot(w)), ears)) {
    return false;
  }
  out.added.clear();
  for (const Tri& e : ears) {
    const auto node = [&](int i) { return i < static_cast<int>(loop.size()) ? loop[i] : hub; };
    const Tri t = {node(e[0]), node(e[1]), node(e[2])};
    Tri sorted = t;
    std::sort(sorted.begin(), sorted.end());
    if (existing.count(sorted)) return false;
    const Vec3 nt = (m.nodes[t[1]] - m.nodes[t[0]]).cross(m.nodes[t[2]] - m.nodes[t[0]]);
    if (!(nt.dot(n) > 0)) return false;
    out.added.push_back(t);
  }
  out.removed = region;
  out.nodesDropped = static_cast<int>(uses.size()) - (hub >= 0 ? 1 : 0);
  return true;
}

}  // namespace

bool retriangulateFold(const SurfaceMesh& mesh, const std::vector<Tri>& tris, const std::vector<int>& seed,
                       const std::vector<int>& useCount, const std::set<Tri>& existing, FoldRepair& out) {
  if (seed.size() == 2)
    for (int side = 0; side < 2; ++side)
      if (replaceRegion(mesh, tris, pocket(mesh, tris, seed[side], seed[1 - side]), useCount, existing, out))
        return true;
  std::vector<int> region = ringAround(tris, seed);
  for (int ring = 0; ring <= kMaxRings; ++ring) {
    if (replaceRegion(mesh, tris, region, useCount, existing, out)) return true;
    region = ringAround(tris, region);
  }
  return false;
}

}  // namespace aniso
