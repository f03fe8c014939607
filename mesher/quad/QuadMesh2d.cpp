#include "mesher/quad/QuadMesh2d.h"

#include <algorithm>
#include <map>
#include <utility>

#include "mesher/core/Error.h"

namespace aniso::quad {

QuadMesh2d QuadMesh2d::fromFaceMesh(const FaceMesh& fm) {
  QuadMesh2d m;
  m.uv = fm.uv;
  m.node = fm.node;
  m.boundary.resize(fm.uv.size());
  for (std::size_t v = 0; v < fm.uv.size(); ++v) m.boundary[v] = fm.node[v] >= 0 ? 1 : 0;
  for (const auto& t : fm.triangles) m.corners.push_back({t[0], t[1], t[2], kNone});
  for (const auto& q : fm.quads) m.corners.push_back({q[0], q[1], q[2], q[3]});
  m.adj.assign(m.corners.size(), {kNone, kNone, kNone, kNone});
  // Link the edges by sorting the directed edges on their undirected key.
  struct Half {
    int lo, hi, e, k;
  };
  std::vector<Half> halves;
  for (int e = 0; e < m.numElements(); ++e) {
    const int n = m.sides(e);
    for (int k = 0; k < n; ++k) {
      const int a = m.corners[e][k], b = m.corners[e][(k + 1) % n];
      halves.push_back({std::min(a, b), std::max(a, b), e, k});
    }
  }
  std::sort(halves.begin(), halves.end(), [](const Half& x, const Half& y) {
    return std::tie(x.lo, x.hi, x.e, x.k) < std::tie(y.lo, y.hi, y.e, y.k);
  });
  for (std::size_t i = 0; i + 1 < halves.size(); ++i) {
    const Half& x = halves[i];
    const Half& y = halves[i + 1];
    if (x.lo != y.lo || x.hi != y.hi) continue;
    if (i + 2 < halves.size() && halves[i + 2].lo == x.lo && halves[i + 2].hi == x.hi)
      throw MeshingError("quad conversion: edge (" + std::to_string(x.lo) + ", " + std::to_string(x.hi) +
                         ") is used by more than two elements");
    m.adj[x.e][x.k] = y.e;
    m.adj[y.e][y.k] = x.e;
    ++i;
  }
  return m;
}

void QuadMesh2d::toFaceMesh(FaceMesh& fm) const {
  fm.uv = uv;
  fm.node = node;
  fm.triangles.clear();
  fm.quads.clear();
  for (int e = 0; e < numElements(); ++e) {
    const Corners& c = corners[e];
    if (sides(e) == 3) fm.triangles.push_back({c[0], c[1], c[2]});
    if (sides(e) == 4) fm.quads.push_back(c);
  }
}

int QuadMesh2d::edgeIndex(int e, int a, int b) const {
  const int n = sides(e);
  for (int k = 0; k < n; ++k)
    if (corners[e][k] == a && corners[e][(k + 1) % n] == b) return k;
  return kNone;
}

int QuadMesh2d::cornerIndex(int e, int v) const {
  const int n = sides(e);
  for (int k = 0; k < n; ++k)
    if (corners[e][k] == v) return k;
  return kNone;
}

int QuadMesh2d::addVertex(const Vec2& p) {
  uv.push_back(p);
  node.push_back(-1);
  boundary.push_back(0);
  return numVertices() - 1;
}

std::vector<int> QuadMesh2d::replacePatch(std::span<const int> removed, std::span<const Corners> added) {
  // The outer links of the patch: directed edge (a, b) of a removed element → the element
  // across it (kNone on the face boundary), or −2 for an edge inside the patch.
  std::map<std::pair<int, int>, int> outer;
  for (int e : removed) {
    const int n = sides(e);
    for (int k = 0; k < n; ++k) {
      const int across = adj[e][k];
      const bool inside = across != kNone && std::find(removed.begin(), removed.end(), across) != removed.end();
      outer[{corners[e][k], corners[e][(k + 1) % n]}] = inside ? -2 : across;
    }
  }
  for (int e : removed) corners[e] = {kNone, kNone, kNone, kNone};
  std::vector<int> ids;
  for (const Corners& c : added) {
    ids.push_back(numElements());
    corners.push_back(c);
    adj.push_back({kNone, kNone, kNone, kNone});
  }
  for (int e : ids) {
    const int n = sides(e);
    for (int k = 0; k < n; ++k) {
      const int a = corners[e][k], b = corners[e][(k + 1) % n];
      int link = kNone;
      for (int f : ids)
        if (f != e && edgeIndex(f, b, a) != kNone) link = f;
      if (link == kNone) {
        const auto it = outer.find({a, b});
        if (it != outer.end() && it->second >= 0) {
          link = it->second;
          const int j = edgeIndex(link, b, a);
          if (j == kNone) throw MeshingError("quad conversion: patch replacement lost an edge link");
          adj[link][j] = e;
        }
      }
      adj[e][k] = link;
    }
  }
  return ids;
}

void QuadMesh2d::star(int v, int e, std::vector<int>& out, bool& closed) const {
  // In element f with v at corner k, the element across the edge (k, k+1) leaving v is the
  // next one clockwise around v, the one across (k−1, k) the next counter-clockwise.
  closed = false;
  std::vector<int> cw;
  int f = e;
  do {
    cw.push_back(f);
    f = adj[f][cornerIndex(f, v)];  // across the edge (v, next): clockwise neighbour
    if (f == e) {
      closed = true;
      break;
    }
  } while (f != kNone && cw.size() < 4096);
  if (closed) {
    // cw lists the elements clockwise from e; report counter-clockwise from e.
    out.push_back(e);
    for (std::size_t i = cw.size(); i-- > 1;) out.push_back(cw[i]);
    return;
  }
  // Open star: walk counter-clockwise from e across the edge (prev, v).
  std::vector<int> ccw;
  f = e;
  while (true) {
    const int n = sides(f), k = cornerIndex(f, v);
    const int g = adj[f][(k + n - 1) % n];
    if (g == kNone || ccw.size() > 4096) break;
    ccw.push_back(g);
    f = g;
  }
  // Counter-clockwise order: from the clockwise end to the counter-clockwise end.
  for (std::size_t i = cw.size(); i-- > 0;) out.push_back(cw[i]);
  for (int g : ccw) out.push_back(g);
}

void QuadMesh2d::compact() {
  std::vector<int> id(corners.size(), kNone);
  int w = 0;
  for (int e = 0; e < numElements(); ++e)
    if (alive(e)) id[e] = w++;
  std::vector<Corners> c2(w), a2(w);
  for (int e = 0; e < numElements(); ++e) {
    if (id[e] == kNone) continue;
    c2[id[e]] = corners[e];
    for (int k = 0; k < 4; ++k) a2[id[e]][k] = adj[e][k] == kNone ? kNone : id[adj[e][k]];
  }
  corners = std::move(c2);
  adj = std::move(a2);
}

void QuadMesh2d::dropUnusedVertices() {
  std::vector<int> id(uv.size(), kNone);
  for (int e = 0; e < numElements(); ++e)
    for (int k = 0; k < sides(e); ++k) id[corners[e][k]] = 0;
  int w = 0;
  for (int v = 0; v < numVertices(); ++v) {
    if (id[v] == kNone && !boundary[v] && node[v] < 0) continue;
    id[v] = w;
    uv[w] = uv[v];
    node[w] = node[v];
    boundary[w] = boundary[v];
    ++w;
  }
  uv.resize(w);
  node.resize(w);
  boundary.resize(w);
  for (int e = 0; e < numElements(); ++e)
    for (int k = 0; k < sides(e); ++k) corners[e][k] = id[corners[e][k]];
}

std::vector<std::string> QuadMesh2d::validate() const {
  std::vector<std::string> bad;
  auto say = [&](int e, const std::string& what) { bad.push_back("element " + std::to_string(e) + ": " + what); };
  for (int e = 0; e < numElements(); ++e) {
    const int n = sides(e);
    if (n == 0) continue;
    for (int k = 0; k < n; ++k) {
      const int a = corners[e][k];
      if (a < 0 || a >= numVertices()) {
        say(e, "corner out of range");
        break;
      }
      for (int j = k + 1; j < n; ++j)
        if (corners[e][j] == a) say(e, "repeated corner " + std::to_string(a));
    }
    for (int k = 0; k < n; ++k) {
      const int a = corners[e][k], b = corners[e][(k + 1) % n], f = adj[e][k];
      if (f == kNone) {
        if (a >= 0 && a < numVertices() && b >= 0 && b < numVertices() && !(boundary[a] && boundary[b]))
          say(e, "open edge (" + std::to_string(a) + ", " + std::to_string(b) + ") inside the face");
        continue;
      }
      if (f < 0 || f >= numElements() || !alive(f)) {
        say(e, "neighbour " + std::to_string(f) + " is not a live element");
        continue;
      }
      const int j = edgeIndex(f, b, a);
      if (j == kNone || adj[f][j] != e) say(e, "adjacency across edge " + std::to_string(k) + " is not symmetric");
    }
  }
  return bad;
}

}  // namespace aniso::quad
