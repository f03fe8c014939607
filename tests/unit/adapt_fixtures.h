#pragma once
// Meshes of the adapt tests (adapt_hessian_test.cpp, adapt_transfer_test.cpp).
#include <random>

#include "mesher/adapt/PatchMesh.h"

namespace aniso {

/// The unit cube (n³ hexahedra, 6 tets each; dim 3) or square (n² quads, 2 triangles
/// each, in the plane z = 0.3 x + 0.1 y; dim 2), interior nodes moved at random by up to
/// 0.3 of the spacing.
inline PatchMesh randomMesh(int dim, int n, unsigned seed) {
  PatchMesh m;
  m.dim = dim;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.3 / n, 0.3 / n);
  const int nz = dim == 3 ? n : 0;
  auto id = [&](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        Vec3 p(double(i) / n, double(j) / n, dim == 3 ? double(k) / n : 0.0);
        const bool inside = i > 0 && i < n && j > 0 && j < n && (dim == 2 || (k > 0 && k < n));
        if (inside) p += Vec3(u(rng), u(rng), dim == 3 ? u(rng) : 0.0);
        if (dim == 2) p.z() = 0.3 * p.x() + 0.1 * p.y();
        m.nodes.push_back(p);
      }
  auto cell = [&](std::initializer_list<int> v) {
    m.conn.insert(m.conn.end(), v);
    m.offsets.push_back(static_cast<int>(m.conn.size()));
  };
  for (int k = 0; k < std::max(nz, 1); ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (dim == 2) {
          cell({id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0)});
          cell({id(i, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)});
          continue;
        }
        const int c[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),     id(i, j + 1, k),
                          id(i, j, k + 1),     id(i + 1, j, k + 1),     id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        // the 6 tets around the diagonal 0-6
        const int t[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
        for (const auto& q : t) cell({c[q[0]], c[q[1]], c[q[2]], c[q[3]]});
      }
  return m;
}

}  // namespace aniso
