#pragma once
// Hand-made solids for the volume mesher's unit tests: a Model whose faces carry no
// geometry (the volume mesher only reads shells, face uses and orientations) and a
// SurfaceMesh with one face per polygon side. Triangles are counter-clockwise seen from
// outside the material.
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso::voltest {

/// Messages one per line (validators' output in an assertion: "" when valid).
inline std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += x + "\n";
  return s;
}

struct SolidModel {
  Model model;
  SurfaceMesh surface;
  double volume = 0;  ///< exact volume of the solid
};

/// Adds a face of n x n grid cells on the square origin + [0,1]^2 spanned by u, v (outward
/// normal u x v), into shell `shell`; nodes shared through `nodeAt`. `diagonalFlip`
/// alternates the diagonals (so that the grid's Delaunay triangulation is ambiguous).
class SolidBuilder {
 public:
  int addNode(const Vec3& p) {
    for (std::size_t i = 0; i < m_.surface.nodes.size(); ++i)
      if ((m_.surface.nodes[i] - p).norm() < 1e-12) return static_cast<int>(i);
    return m_.surface.addNode(p, NodeOn{});
  }
  int addShell() {
    m_.model.shells.push_back({});
    m_.model.shells.back().closed = true;
    return static_cast<int>(m_.model.shells.size()) - 1;
  }
  int addFace(int shell, bool reversedUse = false) {
    m_.model.faces.push_back({});
    const int f = static_cast<int>(m_.model.faces.size()) - 1;
    m_.model.shells[shell].faces.push_back({f, reversedUse});
    return f;
  }
  void addTriangle(int face, int a, int b, int c) {
    m_.surface.triangles.push_back({a, b, c});
    m_.surface.triangleFace.push_back(face);
  }
  void gridFace(int shell, const Vec3& origin, const Vec3& u, const Vec3& v, int n, bool alternate) {
    const int f = addFace(shell);
    std::vector<std::vector<int>> id(n + 1, std::vector<int>(n + 1));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) id[i][j] = addNode(origin + u * (double(i) / n) + v * (double(j) / n));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const int a = id[i][j], b = id[i + 1][j], c = id[i + 1][j + 1], d = id[i][j + 1];
        if (!alternate || (i + j) % 2 == 0) {
          addTriangle(f, a, b, c);
          addTriangle(f, a, c, d);
        } else {
          addTriangle(f, a, b, d);
          addTriangle(f, b, c, d);
        }
      }
  }
  /// The six faces of the box lo + [0, s]^3, outward (inward = true: normals into the box,
  /// for a void shell).
  void box(int shell, const Vec3& lo, double s, int n, bool inward, bool alternate) {
    const Vec3 x(s, 0, 0), y(0, s, 0), z(0, 0, s);
    auto face = [&](const Vec3& o, const Vec3& u, const Vec3& v) {
      if (inward) gridFace(shell, o, v, u, n, alternate);
      else gridFace(shell, o, u, v, n, alternate);
    };
    face(lo, y, x);          // z = lo (normal -z)
    face(lo + z, x, y);      // z = hi
    face(lo, x, z);          // y = lo (normal -y)
    face(lo + y, z, x);      // y = hi
    face(lo, z, y);          // x = lo (normal -x)
    face(lo + x, y, z);      // x = hi
  }
  SolidModel done(double volume) {
    m_.volume = volume;
    Box3 b;
    for (const Vec3& p : m_.surface.nodes) b.add(p);
    m_.model.bbox = b;
    return m_;
  }
  Model& model() { return m_.model; }

 private:
  SolidModel m_;
};

/// The unit cube with an n x n grid on each face (coplanar and cospherical nodes).
inline SolidModel gridCube(int n, bool alternate) {
  SolidBuilder b;
  const int shell = b.addShell();
  b.box(shell, Vec3(0, 0, 0), 1.0, n, false, alternate);
  b.model().solids.push_back({"CUBE", shell, {}});
  return b.done(1.0);
}

/// The unit cube with a cubic void of side s centred in it.
inline SolidModel cubeWithVoid(int n, double s) {
  SolidBuilder b;
  const int outer = b.addShell();
  b.box(outer, Vec3(0, 0, 0), 1.0, n, false, false);
  const int inner = b.addShell();
  const double lo = 0.5 - s / 2;
  b.box(inner, Vec3(lo, lo, lo), s, n, true, true);
  b.model().solids.push_back({"HOLLOW", outer, {inner}});
  return b.done(1.0 - s * s * s);
}

/// Schönhardt's twisted prism: two equilateral triangles (radius 1, heights 0 and h), the
/// top one turned by `twist` radians; the sides are split along the diagonals that make it
/// non-convex, so it has no tetrahedralization without a Steiner point.
inline SolidModel schoenhardtPrism(double h = 1.0, double twist = 0.5) {
  SolidBuilder b;
  const int shell = b.addShell();
  int bot[3], top[3];
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * M_PI * k / 3;
    bot[k] = b.addNode(Vec3(std::cos(a), std::sin(a), 0));
    top[k] = b.addNode(Vec3(std::cos(a + twist), std::sin(a + twist), h));
  }
  const int fb = b.addFace(shell), ft = b.addFace(shell), fs = b.addFace(shell);
  b.addTriangle(fb, bot[0], bot[2], bot[1]);
  b.addTriangle(ft, top[0], top[1], top[2]);
  for (int k = 0; k < 3; ++k) {
    const int k1 = (k + 1) % 3;
    // Quad bot[k] bot[k1] top[k1] top[k], split by the diagonal bot[k]-top[k1] (reflex).
    b.addTriangle(fs, bot[k], bot[k1], top[k1]);
    b.addTriangle(fs, bot[k], top[k1], top[k]);
  }
  b.model().solids.push_back({"SCHOENHARDT", shell, {}});
  SolidModel m = b.done(0);
  // Exact volume from the boundary (divergence theorem).
  double v = 0;
  for (const auto& t : m.surface.triangles)
    v += m.surface.nodes[t[0]].dot(m.surface.nodes[t[1]].cross(m.surface.nodes[t[2]])) / 6.0;
  m.volume = v;
  return m;
}

/// A film over the unit square, `thickness` thick, whose top and bottom are the same
/// triangulation (an n x n grid, interior nodes jittered by up to `jitter` cells, each cell
/// split by its shorter diagonal): each top node above a bottom one, shifted sideways by up
/// to `offset` cells (a CAD's top and bottom faces meshed alike). Sides: one strip of
/// triangles per boundary segment.
inline SolidModel columnFilm(int n, double thickness, double jitter, double offset) {
  SolidBuilder b;
  const int shell = b.addShell();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0 / n, 1.0 / n);
  std::vector<std::vector<Vec3>> p(n + 1, std::vector<Vec3>(n + 1));
  std::vector<std::vector<int>> bot(n + 1, std::vector<int>(n + 1)), top = bot;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const bool inner = i > 0 && i < n && j > 0 && j < n;
      p[i][j] = Vec3(double(i) / n + (inner ? jitter * u(rng) : 0), double(j) / n + (inner ? jitter * u(rng) : 0), 0);
      bot[i][j] = b.addNode(p[i][j]);
      const Vec3 shift = inner ? Vec3(offset * u(rng), offset * u(rng), 0) : Vec3(0, 0, 0);
      top[i][j] = b.addNode(p[i][j] + shift + Vec3(0, 0, thickness));
    }
  const int fb = b.addFace(shell), ft = b.addFace(shell), fs = b.addFace(shell);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const bool main = (p[i][j] - p[i + 1][j + 1]).norm() < (p[i + 1][j] - p[i][j + 1]).norm();
      const std::array<std::array<int, 2>, 6> c =
          main ? std::array<std::array<int, 2>, 6>{{{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j}, {i + 1, j + 1}, {i, j + 1}}}
               : std::array<std::array<int, 2>, 6>{{{i, j}, {i + 1, j}, {i, j + 1}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
      for (int k = 0; k < 6; k += 3) {
        b.addTriangle(ft, top[c[k][0]][c[k][1]], top[c[k + 1][0]][c[k + 1][1]], top[c[k + 2][0]][c[k + 2][1]]);
        b.addTriangle(fb, bot[c[k][0]][c[k][1]], bot[c[k + 2][0]][c[k + 2][1]], bot[c[k + 1][0]][c[k + 1][1]]);
      }
    }
  std::vector<std::array<int, 2>> ring;  // the boundary, counter-clockwise
  for (int i = 0; i < n; ++i) ring.push_back({i, 0});
  for (int j = 0; j < n; ++j) ring.push_back({n, j});
  for (int i = n; i > 0; --i) ring.push_back({i, n});
  for (int j = n; j > 0; --j) ring.push_back({0, j});
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const auto [i0, j0] = ring[k];
    const auto [i1, j1] = ring[(k + 1) % ring.size()];
    b.addTriangle(fs, bot[i0][j0], bot[i1][j1], top[i1][j1]);
    b.addTriangle(fs, bot[i0][j0], top[i1][j1], top[i0][j0]);
  }
  b.model().solids.push_back({"FILM", shell, {}});
  return b.done(thickness);
}

}  // namespace aniso::voltest
