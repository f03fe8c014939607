#include "tests/io/BoxFixture.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <map>
#include <stdexcept>

namespace aniso::testing {
namespace {

/// Face id (0-based) of the side `s` (0 low, 1 high) of axis `a`: OCCT's box order.
int faceOf(int a, int s) { return 2 * a + s; }

/// Corner index of the vertex with bits (i, j, k).
int corner(int i, int j, int k) { return i + 2 * j + 4 * k; }

/// Edge index of the edge along axis `a` whose other two coordinates have bits (b1, b2).
int edgeOf(int a, int b1, int b2) { return 4 * a + b1 + 2 * b2; }

/// Grid of (cells + 1)^3 points with the node classification of each.
struct Grid {
  Vec3 size;
  std::array<int, 3> cells;
  int index(int i, int j, int k) const { return i + (cells[0] + 1) * (j + (cells[1] + 1) * k); }
  Vec3 point(const std::array<int, 3>& g) const {
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = size[a] * g[a] / cells[a];
    return p;
  }
};

/// Classifies a point with doubled grid coordinates `h` (so mid-edge points are integer)
/// by the box entity it lies on.
NodeOn classify(const std::array<int, 3>& h, const std::array<int, 3>& cells) {
  int bits[3], onBoundary = 0;
  for (int a = 0; a < 3; ++a) {
    bits[a] = h[a] == 0 ? 0 : (h[a] == 2 * cells[a] ? 1 : -1);
    onBoundary += bits[a] >= 0;
  }
  NodeOn on;
  if (onBoundary == 3) {
    on.kind = NodeOn::Kind::Vertex;
    on.entity = corner(bits[0], bits[1], bits[2]);
  } else if (onBoundary == 2) {
    const int a = bits[0] < 0 ? 0 : (bits[1] < 0 ? 1 : 2);
    on.kind = NodeOn::Kind::Edge;
    on.entity = edgeOf(a, bits[(a + 1) % 3 < (a + 2) % 3 ? (a + 1) % 3 : (a + 2) % 3],
                       bits[(a + 1) % 3 < (a + 2) % 3 ? (a + 2) % 3 : (a + 1) % 3]);
    on.t = h[a] * 0.5 / cells[a];
  } else if (onBoundary == 1) {
    const int a = bits[0] >= 0 ? 0 : (bits[1] >= 0 ? 1 : 2);
    on.kind = NodeOn::Kind::Face;
    on.entity = faceOf(a, bits[a]);
    on.uv = Vec2(h[(a + 1) % 3] * 0.5, h[(a + 2) % 3] * 0.5);
  } else {
    on.kind = NodeOn::Kind::Solid;
    on.entity = 0;
  }
  return on;
}

/// Mid-edge nodes, created once per edge.
struct MidNodes {
  SurfaceMesh& mesh;
  const std::vector<std::array<int, 3>>& doubled;  // doubled grid coordinates per node
  std::array<int, 3> cells;
  std::map<std::pair<int, int>, int> made;
  std::vector<std::array<int, 3>> extra;
  int operator()(int a, int b) {
    const auto key = std::minmax(a, b);
    const auto it = made.find(key);
    if (it != made.end()) return it->second;
    std::array<int, 3> h;
    for (int k = 0; k < 3; ++k) h[k] = (coords(a)[k] + coords(b)[k]) / 2;
    const int n = mesh.addNode(0.5 * (mesh.nodes[a] + mesh.nodes[b]), classify(h, cells));
    extra.push_back(h);
    made.emplace(key, n);
    return n;
  }
  std::array<int, 3> coords(int n) const {
    return n < static_cast<int>(doubled.size()) ? doubled[n] : extra[n - doubled.size()];
  }
};

double volume6(const std::vector<Vec3>& p, const std::array<int, 4>& t) {
  return (p[t[1]] - p[t[0]]).dot((p[t[2]] - p[t[0]]).cross(p[t[3]] - p[t[0]]));
}

/// The face id of a boundary facet with doubled grid coordinates, or -1.
int facetFace(const std::array<std::array<int, 3>, 3>& h, const std::array<int, 3>& cells) {
  for (int a = 0; a < 3; ++a)
    for (int s = 0; s < 2; ++s) {
      const int v = s * 2 * cells[a];
      if (h[0][a] == v && h[1][a] == v && h[2][a] == v) return faceOf(a, s);
    }
  return -1;
}

/// Adds the grid nodes: those on the boundary first, then (with `interior`) the others.
/// Returns the node of every grid point (-1 for interior points left out).
std::vector<int> addGridNodes(const Grid& g, SurfaceMesh& sm, std::vector<std::array<int, 3>>& doubled,
                              bool interior) {
  std::vector<int> node((g.cells[0] + 1) * (g.cells[1] + 1) * (g.cells[2] + 1), -1);
  for (int pass = 0; pass < 2; ++pass)
    for (int k = 0; k <= g.cells[2]; ++k)
      for (int j = 0; j <= g.cells[1]; ++j)
        for (int i = 0; i <= g.cells[0]; ++i) {
          const std::array<int, 3> h{2 * i, 2 * j, 2 * k};
          const NodeOn on = classify(h, g.cells);
          if ((on.kind == NodeOn::Kind::Solid) != (pass == 1) || (pass == 1 && !interior)) continue;
          node[g.index(i, j, k)] = sm.addNode(g.point({i, j, k}), on);
          doubled.push_back(h);
        }
  return node;
}

}  // namespace

Model boxModel(const Vec3& size, const std::string& name) {
  Model m;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) m.vertices.push_back({Vec3(i * size[0], j * size[1], k * size[2]), 1e-7});
  m.edges.resize(12);
  for (int a = 0; a < 3; ++a)
    for (int b2 = 0; b2 < 2; ++b2)
      for (int b1 = 0; b1 < 2; ++b1) {
        // b1, b2: bits of the other two axes in increasing axis order
        std::array<int, 3> lo{0, 0, 0};
        const int o1 = std::min((a + 1) % 3, (a + 2) % 3), o2 = std::max((a + 1) % 3, (a + 2) % 3);
        lo[o1] = b1;
        lo[o2] = b2;
        std::array<int, 3> hi = lo;
        hi[a] = 1;
        ModelEdge& e = m.edges[edgeOf(a, b1, b2)];
        e.v0 = corner(lo[0], lo[1], lo[2]);
        e.v1 = corner(hi[0], hi[1], hi[2]);
        e.t1 = size[a];
      }
  m.faces.resize(6);
  ModelShell shell;
  shell.closed = true;
  for (int a = 0; a < 3; ++a)
    for (int s = 0; s < 2; ++s) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      std::array<int, 4> ring;  // counter-clockwise around +e_a in the (b, c) plane
      const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int q = 0; q < 4; ++q) {
        std::array<int, 3> bits{};
        bits[a] = s;
        bits[b] = uv[q][0];
        bits[c] = uv[q][1];
        ring[q] = corner(bits[0], bits[1], bits[2]);
      }
      if (s == 0) std::reverse(ring.begin(), ring.end());
      Loop loop;
      loop.outer = true;
      for (int q = 0; q < 4; ++q) {
        const int p0 = ring[q], p1 = ring[(q + 1) % 4];
        for (int e = 0; e < 12; ++e) {
          const ModelEdge& me = m.edges[e];
          if ((me.v0 == p0 && me.v1 == p1) || (me.v0 == p1 && me.v1 == p0)) {
            loop.uses.push_back({e, me.v0 != p0, -1});
            m.edges[e].faces.push_back(faceOf(a, s));
          }
        }
      }
      m.faces[faceOf(a, s)].loops.push_back(loop);
      m.faces[faceOf(a, s)].uvBounds.add(Vec2(0, 0));
      m.faces[faceOf(a, s)].uvBounds.add(Vec2(size[b], size[c]));
    }
  for (int f = 0; f < 6; ++f) shell.faces.push_back({f, false});
  m.shells.push_back(shell);
  m.solids.push_back({name, 0, {}});
  m.bbox.add(Vec3::Zero());
  m.bbox.add(size);
  return m;
}

VolumeMesh boxTets(const Vec3& size, const std::array<int, 3>& cells, bool quadratic) {
  const Grid g{size, cells};
  VolumeMesh vm;
  SurfaceMesh& sm = vm.surface;
  std::vector<std::array<int, 3>> doubled;
  const std::vector<int> node = addGridNodes(g, sm, doubled, true);
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i)
        for (const auto& p : perms) {
          std::array<int, 3> at{i, j, k};
          std::array<int, 4> t;
          t[0] = node[g.index(at[0], at[1], at[2])];
          for (int s = 0; s < 3; ++s) {
            ++at[p[s]];
            t[s + 1] = node[g.index(at[0], at[1], at[2])];
          }
          if (volume6(sm.nodes, t) < 0) std::swap(t[1], t[2]);
          vm.tets.push_back(t);
          vm.tetSolid.push_back(0);
        }
  // Boundary facets: the tetrahedron faces used once, oriented outward.
  std::map<std::array<int, 3>, std::pair<int, int>> facets;  // sorted nodes -> (count, tet*4+face)
  for (size_t t = 0; t < vm.tets.size(); ++t)
    for (int f = 0; f < 4; ++f) {
      std::array<int, 3> key{vm.tets[t][(f + 1) % 4], vm.tets[t][(f + 2) % 4], vm.tets[t][(f + 3) % 4]};
      std::sort(key.begin(), key.end());
      auto& e = facets[key];
      ++e.first;
      e.second = static_cast<int>(t) * 4 + f;
    }
  for (const auto& [key, e] : facets) {
    if (e.first != 1) continue;
    const auto& t = vm.tets[e.second / 4];
    const int f = e.second % 4;
    std::array<int, 3> tri{t[(f + 1) % 4], t[(f + 2) % 4], t[(f + 3) % 4]};
    const Vec3 n = (sm.nodes[tri[1]] - sm.nodes[tri[0]]).cross(sm.nodes[tri[2]] - sm.nodes[tri[0]]);
    if (n.dot(sm.nodes[t[f]] - sm.nodes[tri[0]]) > 0) std::swap(tri[1], tri[2]);
    const int face = facetFace({doubled[tri[0]], doubled[tri[1]], doubled[tri[2]]}, cells);
    if (face < 0) throw std::logic_error("boxTets: a boundary facet off the box faces");
    sm.triangles.push_back(tri);
    sm.triangleFace.push_back(face);
  }
  if (quadratic) {
    MidNodes mid{sm, doubled, cells, {}, {}};
    for (const auto& t : vm.tets) {
      std::array<int, 6> m6;
      for (int k = 0; k < 6; ++k) m6[k] = mid(t[VolumeMesh::kTetEdges[k][0]], t[VolumeMesh::kTetEdges[k][1]]);
      vm.tetMid.push_back(m6);
    }
    for (const auto& tri : sm.triangles) sm.triangleMid.push_back({mid(tri[0], tri[1]), mid(tri[1], tri[2]), mid(tri[2], tri[0])});
  }
  return vm;
}

SurfaceMesh boxSurface(const Vec3& size, const std::array<int, 3>& cells, bool quadratic) {
  const Grid g{size, cells};
  SurfaceMesh sm;
  std::vector<std::array<int, 3>> doubled;
  const std::vector<int> node = addGridNodes(g, sm, doubled, false);
  for (int a = 0; a < 3; ++a)
    for (int s = 0; s < 2; ++s) {
      const int b = (a + 1) % 3, c = (a + 2) % 3, face = faceOf(a, s);
      for (int v = 0; v < cells[c]; ++v)
        for (int u = 0; u < cells[b]; ++u) {
          std::array<int, 4> q;
          const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
          for (int r = 0; r < 4; ++r) {
            std::array<int, 3> at{};
            at[a] = s * cells[a];
            at[b] = u + uv[r][0];
            at[c] = v + uv[r][1];
            q[r] = node[g.index(at[0], at[1], at[2])];
          }
          if (s == 0) std::reverse(q.begin(), q.end());
          if (face == 5) {
            sm.triangles.push_back({q[0], q[1], q[2]});
            sm.triangles.push_back({q[0], q[2], q[3]});
            sm.triangleFace.insert(sm.triangleFace.end(), 2, face);
          } else {
            sm.quads.push_back(q);
            sm.quadFace.push_back(face);
          }
        }
    }
  if (quadratic) {
    MidNodes mid{sm, doubled, cells, {}, {}};
    for (const auto& t : sm.triangles) sm.triangleMid.push_back({mid(t[0], t[1]), mid(t[1], t[2]), mid(t[2], t[0])});
    for (const auto& q : sm.quads)
      sm.quadMid.push_back({mid(q[0], q[1]), mid(q[1], q[2]), mid(q[2], q[3]), mid(q[3], q[0])});
  }
  return sm;
}

void appendShifted(Model& a, VolumeMesh& am, const Model& b, const VolumeMesh& bm, const Vec3& shift) {
  const int nv = static_cast<int>(a.vertices.size()), ne = static_cast<int>(a.edges.size());
  const int nf = static_cast<int>(a.faces.size()), nsh = static_cast<int>(a.shells.size());
  const int nso = static_cast<int>(a.solids.size()), nn = static_cast<int>(am.surface.nodes.size());
  for (ModelVertex v : b.vertices) {
    v.p += shift;
    a.vertices.push_back(v);
    a.bbox.add(v.p);
  }
  for (ModelEdge e : b.edges) {
    e.v0 += nv;
    e.v1 += nv;
    for (int& f : e.faces) f += nf;
    a.edges.push_back(e);
  }
  for (ModelFace f : b.faces) {
    for (Loop& l : f.loops)
      for (EdgeUse& u : l.uses) u.edge += ne;
    a.faces.push_back(f);
  }
  for (ModelShell s : b.shells) {
    for (FaceUse& u : s.faces) u.face += nf;
    a.shells.push_back(s);
  }
  for (ModelSolid s : b.solids) {
    s.outerShell += nsh;
    a.solids.push_back(s);
  }
  const SurfaceMesh& bs = bm.surface;
  SurfaceMesh& as = am.surface;
  for (size_t i = 0; i < bs.nodes.size(); ++i) {
    NodeOn on = bs.nodeOn[i];
    on.entity += on.kind == NodeOn::Kind::Vertex ? nv : on.kind == NodeOn::Kind::Edge ? ne
                 : on.kind == NodeOn::Kind::Face ? nf : nso;
    as.addNode(bs.nodes[i] + shift, on);
  }
  auto shifted = [&](auto arr) {
    for (int& v : arr) v += nn;
    return arr;
  };
  for (size_t t = 0; t < bs.triangles.size(); ++t) {
    as.triangles.push_back(shifted(bs.triangles[t]));
    as.triangleFace.push_back(bs.triangleFace[t] + nf);
  }
  for (const auto& m : bs.triangleMid) as.triangleMid.push_back(shifted(m));
  for (size_t t = 0; t < bm.tets.size(); ++t) {
    am.tets.push_back(shifted(bm.tets[t]));
    am.tetSolid.push_back(bm.tetSolid[t] + nso);
  }
  for (const auto& m : bm.tetMid) am.tetMid.push_back(shifted(m));
}

}  // namespace aniso::testing
