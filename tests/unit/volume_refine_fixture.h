#pragma once
// Fixtures of the volume refinement / improvement / quality tests: a SolidTetMesh of the
// unit cube built without boundary recovery (the Delaunay triangulation of points on the
// cube's surface, box tets removed, hull faces constrained, node[] = point index), and
// the invariant check that stands in for validateSolidTetMesh.
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "mesher/delaunay3d/Delaunay3d.h"
#include "mesher/delaunay3d/LocalRetriangulation.h"
#include "mesher/delaunay3d/RemoveTets.h"
#include "mesher/delaunay3d/Validate.h"
#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/SolidTetMesh.h"

namespace aniso::testing {

using Triple = std::array<int, 3>;

inline Triple sortedTriple(int a, int b, int c) {
  Triple t{a, b, c};
  std::sort(t.begin(), t.end());
  return t;
}

/// Points on the surface of [0,1]^3: an n×n grid per face, jittered within the face (edge
/// points along their edge, corners fixed), deterministic.
inline std::vector<Vec3> cubeSurfacePoints(int n, std::uint64_t seed = 7) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jit(-0.3 / n, 0.3 / n);
  std::map<std::array<long, 3>, Vec3> pts;  // keyed by the grid position (deduplicates)
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side <= 1; ++side)
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
          std::array<long, 3> key{};
          key[axis] = side * n;
          key[(axis + 1) % 3] = i;
          key[(axis + 2) % 3] = j;
          if (pts.count(key)) continue;
          Vec3 p;
          for (int c = 0; c < 3; ++c) {
            const long k = key[c];
            const bool onBound = k == 0 || k == n;
            p[c] = static_cast<double>(k) / n + (onBound ? 0.0 : jit(rng));
          }
          pts.emplace(key, p);
        }
  std::vector<Vec3> out;
  for (const auto& [k, p] : pts) out.push_back(p);
  return out;
}

/// The solid (the cube mapped by the linear map `map`, triangulated Delaunay for the cube
/// or, with !delaunayInMap, for the mapped points): every hull face constrained;
/// `boundary` gets the hull faces as sorted point index triples. With !removeBox the
/// enclosing box stays (the triangulation before carving) and `boundary` is left empty.
inline SolidTetMesh cubeSolid(int n, std::set<Triple>& boundary, std::uint64_t seed = 7,
                              const Mat3& map = Mat3::Identity(), bool delaunayInMap = true,
                              bool removeBox = true) {
  std::vector<Vec3> pts = cubeSurfacePoints(n, seed);
  for (Vec3& p : pts) p = map * p;
  SolidTetMesh s;
  s.solid = 0;
  del3d::DelaunayOptions opt;
  opt.removeBox = removeBox;
  opt.boxMargin = 10.0;
  // Delaunay where the points are the cube's (sec. 5.3: in metric space), or in space
  if (delaunayInMap) opt.transform = map.inverse();
  const del3d::DelaunayResult r = del3d::buildDelaunay(s.mesh, pts, opt);
  s.node.assign(s.mesh.numVertices(), -1);
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (r.vertexOf[i].valid()) s.node[r.vertexOf[i].index] = static_cast<int>(i);
  boundary.clear();
  for (std::uint32_t k = 0; k < s.mesh.tetSlots() && removeBox; ++k) {
    const del3d::TetId t(k);
    if (!s.mesh.isAlive(t)) continue;
    for (int i = 0; i < 4; ++i) {
      if (s.mesh.neighbour(t, i).valid()) continue;
      s.mesh.setConstrained(t, i, true);
      const std::uint32_t* tv = s.mesh.tetVertices(t);
      boundary.insert(sortedTriple(s.node[tv[del3d::kFaceVertex[i][0]]], s.node[tv[del3d::kFaceVertex[i][1]]],
                                   s.node[tv[del3d::kFaceVertex[i][2]]]));
    }
  }
  return s;
}

/// del3d::validate, validateSolidTetMesh, and the invariants again by hand: node sized to
/// the vertices, hull faces = `boundary` (by node), all constrained, no interior face
/// constrained, hull vertices fixed.
inline std::vector<std::string> checkSolid(const SolidTetMesh& s, const std::set<Triple>& boundary) {
  std::vector<std::string> out = del3d::validate(s.mesh);
  if (s.node.size() != s.mesh.numVertices()) out.push_back("node[] not sized to the vertices");
  std::set<Triple> hull;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k) {
    const del3d::TetId t(k);
    if (!s.mesh.isAlive(t)) continue;
    const std::uint32_t* tv = s.mesh.tetVertices(t);
    for (int i = 0; i < 4; ++i) {
      const bool isHull = !s.mesh.neighbour(t, i).valid();
      if (isHull != s.mesh.isConstrained(t, i)) out.push_back("face constrained bit differs from hull");
      if (!isHull) continue;
      const int a = s.node[tv[del3d::kFaceVertex[i][0]]], b = s.node[tv[del3d::kFaceVertex[i][1]]],
                c = s.node[tv[del3d::kFaceVertex[i][2]]];
      if (a < 0 || b < 0 || c < 0) out.push_back("hull face with a free vertex");
      hull.insert(sortedTriple(a, b, c));
    }
  }
  if (hull != boundary) out.push_back("hull differs from the boundary triangles");
  const std::vector<std::string> contract =
      validateSolidTetMesh(s, std::vector<std::array<int, 3>>(boundary.begin(), boundary.end()));
  out.insert(out.end(), contract.begin(), contract.end());
  return out;
}

/// The model (one solid, one shell, the 6 faces of the cube) and the surface mesh (the
/// solid's hull: node i = point i of cubeSurfacePoints, each triangle on the face of the
/// axis its normal follows) of a cubeSolid, for buildVolumeControlSpace.
struct CubeSurface {
  Model model;
  SurfaceMesh surface;
};

inline CubeSurface cubeSurface(const SolidTetMesh& s, const std::set<Triple>& boundary) {
  CubeSurface c;
  c.model.faces.resize(6);
  c.model.shells.resize(1);
  for (int f = 0; f < 6; ++f) c.model.shells[0].faces.push_back(FaceUse{f, false});
  c.model.solids.push_back(ModelSolid{"cube", 0, {}, {}});
  std::vector<Vec3> at(s.node.size());
  int nodes = 0;
  for (std::uint32_t v = 0; v < s.node.size(); ++v)
    if (s.node[v] >= 0) {
      nodes = std::max(nodes, s.node[v] + 1);
      at[static_cast<std::size_t>(s.node[v])] = s.mesh.point(del3d::VertexId(v));
    }
  at.resize(static_cast<std::size_t>(nodes));
  for (const Vec3& p : at) {
    c.surface.addNode(p, NodeOn{});
    c.model.bbox.add(p);
  }
  for (const Triple& t : boundary) {
    const Vec3 n = (at[t[1]] - at[t[0]]).cross(at[t[2]] - at[t[0]]);
    int axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    const Vec3 centre = (at[t[0]] + at[t[1]] + at[t[2]]) / 3;
    c.surface.triangles.push_back(t);
    c.surface.triangleFace.push_back(2 * axis +
                                     (centre[axis] > c.model.bbox.lo[axis] + 0.5 * c.model.bbox.size()[axis]));
  }
  return c;
}

inline double meshVolume(const del3d::TetMesh& m) {
  double v = 0;
  for (std::uint32_t k = 0; k < m.tetSlots(); ++k) {
    const del3d::TetId t(k);
    if (!m.isAlive(t)) continue;
    const Vec3 a = m.point(m.vertex(t, 0)), b = m.point(m.vertex(t, 1)), c = m.point(m.vertex(t, 2)),
               d = m.point(m.vertex(t, 3));
    v += (b - a).cross(c - a).dot(d - a) / 6.0;
  }
  return v;
}

inline std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += x + "\n";
  return s;
}

inline Box3 unitBox() {
  Box3 b;
  b.add(Vec3(0, 0, 0));
  b.add(Vec3(1, 1, 1));
  return b;
}

/// Same coordinates, same tet slots with the same vertices (determinism checks).
inline bool sameMesh(const SolidTetMesh& a, const SolidTetMesh& b) {
  if (a.mesh.xyz() != b.mesh.xyz() || a.mesh.tetSlots() != b.mesh.tetSlots() || a.node != b.node) return false;
  for (std::uint32_t k = 0; k < a.mesh.tetSlots(); ++k) {
    const del3d::TetId t(k);
    if (a.mesh.isAlive(t) != b.mesh.isAlive(t)) return false;
    if (!a.mesh.isAlive(t)) continue;
    for (int i = 0; i < 4; ++i)
      if (a.mesh.vertex(t, i) != b.mesh.vertex(t, i)) return false;
  }
  return true;
}

/// Positions of the fixed vertices, by node.
inline std::map<int, Vec3> fixedPositions(const SolidTetMesh& s) {
  std::map<int, Vec3> out;
  for (std::uint32_t v = 0; v < s.node.size(); ++v)
    if (s.node[v] >= 0) out[s.node[v]] = s.mesh.point(del3d::VertexId(v));
  return out;
}

/// Kernel vertex of point i: the first 8 vertices are the enclosing-box corners (in no tet).
inline del3d::VertexId pv(int i) { return del3d::VertexId(static_cast<std::uint32_t>(8 + i)); }

/// A solid from points (all of them surface nodes: node[pv(i)] = i) and tets (made
/// positive), faces with equal vertex triples linked, the hull constrained; `boundary`
/// gets the hull as point triples.
inline SolidTetMesh solidFrom(const std::vector<Vec3>& pts, const std::vector<std::array<int, 4>>& tets,
                       std::set<Triple>& boundary) {
  SolidTetMesh s;
  s.solid = 0;
  for (int c = 0; c < 8; ++c) s.mesh.addVertex(Vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1) * 100.0 - Vec3(50, 50, 50));
  for (const Vec3& p : pts) s.mesh.addVertex(p);
  s.node.assign(s.mesh.numVertices(), -1);
  for (std::size_t i = 0; i < pts.size(); ++i) s.node[pv(static_cast<int>(i)).index] = static_cast<int>(i);
  std::map<Triple, std::pair<del3d::TetId, int>> open;
  for (const auto& q : tets) {
    std::array<del3d::VertexId, 4> v = {pv(q[0]), pv(q[1]), pv(q[2]), pv(q[3])};
    if (del3d::orientation(s.mesh, v) < 0) std::swap(v[0], v[1]);
    const del3d::TetId t = s.mesh.createTet(v[0], v[1], v[2], v[3]);
    for (const del3d::VertexId x : v) s.mesh.setVertexTet(x, t);
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t* tv = s.mesh.tetVertices(t);
      const Triple key = sortedTriple(s.node[tv[del3d::kFaceVertex[i][0]]], s.node[tv[del3d::kFaceVertex[i][1]]],
                                      s.node[tv[del3d::kFaceVertex[i][2]]]);
      const auto it = open.find(key);
      if (it == open.end()) {
        open.emplace(key, std::make_pair(t, i));
        continue;
      }
      s.mesh.link(t, i, it->second.first, it->second.second);
      open.erase(it);
    }
  }
  boundary.clear();
  for (const auto& [key, face] : open) {
    s.mesh.setConstrained(face.first, face.second, true);
    boundary.insert(key);
  }
  return s;
}

}  // namespace aniso::testing
