// Unit tests of the cached circumsphere filter (mesher/delaunay3d/Circumsphere.h) and of the
// Inserter's sphere cache: the filter agrees with the exact insphere wherever it decides
// (random, nearly cospherical, exactly cospherical, sliver and far-from-origin cases), it
// decides the common case, and insertions with the cache build the same meshes as without.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mesher/delaunay3d/Circumsphere.h"
#include "mesher/delaunay3d/EnclosingBox.h"
#include "mesher/delaunay3d/Inserter.h"
#include "mesher/delaunay3d/Validate.h"
#include "mesher/predicates/Predicates.h"

using namespace aniso;
using namespace aniso::del3d;

namespace {

struct Tet {
  double p[4][3];
};

Tet randomTet(std::mt19937_64& rng, double offset, double size) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Tet t;
  for (auto& v : t.p)
    for (double& x : v) x = offset + size * u(rng);
  return t;
}

// Counts the cases decided by the filter; fails the test on a disagreement.
int check(const Tet& t, const double* q) {
  EXPECT_TRUE(sphereFilterAgrees(t.p[0], t.p[1], t.p[2], t.p[3], q))
      << q[0] << " " << q[1] << " " << q[2];
  return sphereSide(cachedSphere(t.p[0], t.p[1], t.p[2], t.p[3]), q) != 0;
}

}  // namespace

TEST(Circumsphere, RandomTetsAndPointsAgreeAndAreMostlyDecided) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const double offset : {0.0, -3.5, 1e6}) {
    int decided = 0, total = 0;
    for (int k = 0; k < 20000; ++k) {
      const Tet t = randomTet(rng, offset, 1.0);
      const double q[3] = {offset + 1.5 * u(rng) - 0.25, offset + 1.5 * u(rng) - 0.25, offset + 1.5 * u(rng) - 0.25};
      decided += check(t, q);
      ++total;
    }
    // Far from the origin (1e6, unit tets) the centre's rounding (1e-10 relative to the
    // coordinates) is still far below η r.
    EXPECT_GT(decided, 0.95 * total) << "offset " << offset;
  }
}

TEST(Circumsphere, NearlyCosphericalPointsAgree) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 20000; ++k) {
    const Tet t = randomTet(rng, 0.25, 1.0);
    const CachedSphere s = cachedSphere(t.p[0], t.p[1], t.p[2], t.p[3]);
    if (std::isnan(s.radius2)) continue;
    // A point on the computed sphere, moved radially by a relative 10^-e.
    double dir[3] = {u(rng), u(rng), u(rng)};
    const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    const double r = std::sqrt(sphereRadius2(s));
    const double rel = std::pow(10.0, -static_cast<double>(k % 16)) * (k % 2 ? 1 : -1);
    double q[3];
    for (int i = 0; i < 3; ++i) q[i] = s.centre[i] + r * (1 + rel) * dir[i] / n;
    check(t, q);
    // The vertices themselves lie on the sphere: never decided.
    for (const auto& v : t.p) EXPECT_EQ(sphereSide(s, v), 0);
  }
}

TEST(Circumsphere, CosphericalGridAndSliversAgree) {
  // Unit cube corners: every corner is on the circumsphere of every corner tet.
  const double c[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  int tets = 0;
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      for (int d = b + 1; d < 8; ++d)
        for (int e = d + 1; e < 8; ++e) {
          if (predicates::orient3d(c[a], c[b], c[d], c[e]) == 0) continue;
          ++tets;
          const CachedSphere s = cachedSphere(c[a], c[b], c[d], c[e]);
          for (const auto& q : c) {
            EXPECT_EQ(sphereSide(s, q), 0);
            EXPECT_TRUE(sphereFilterAgrees(c[a], c[b], c[d], c[e], q));
          }
        }
  EXPECT_GT(tets, 50);
  // Slivers: four points near a circle's plane, flattened by 10^-e.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 5000; ++k) {
    const double h = std::pow(10.0, -static_cast<double>(k % 17));
    Tet t;
    for (int i = 0; i < 4; ++i) {
      const double angle = 1.5707963267948966 * i + 0.3 * u(rng);
      t.p[i][0] = std::cos(angle), t.p[i][1] = std::sin(angle), t.p[i][2] = (i % 2 ? h : -h) * (1 + 0.1 * u(rng));
    }
    const double q[3] = {1.2 * u(rng), 1.2 * u(rng), 0.5 * u(rng)};
    check(t, q);
  }
}

TEST(Circumsphere, InserterWithSphereCacheBuildsTheSameMesh) {
  // Random points and a cospherical grid, inserted with and without the cache; on a mesh
  // not certified Delaunay the cavity faces are checked by orient3d without the cache and
  // by the spheres' power test (Inserter::visibleByPower) with it.
  std::vector<Vec3> pts;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 3000; ++k) pts.emplace_back(u(rng), u(rng), u(rng));
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) pts.emplace_back(0.2 * i, 0.2 * j, 0.2 * k);
  Box3 box;
  for (const Vec3& p : pts) box.add(p);
  for (const bool certified : {true, false}) {
    TetMesh plain, cached;
    createEnclosingBox(plain, box);
    createEnclosingBox(cached, box);
    plain.setCertifiedDelaunay(certified);
    cached.setCertifiedDelaunay(certified);
    Inserter a(plain), b(cached);
    b.cacheSpheres();
    for (const Vec3& p : pts) {
      const InsertResult ra = a.insert(p), rb = b.insert(p);
      ASSERT_EQ(ra.status, rb.status);
      ASSERT_EQ(ra.cavityTets, rb.cavityTets);
    }
    ASSERT_EQ(plain.tetSlots(), cached.tetSlots());
    for (std::uint32_t k = 0; k < plain.tetSlots(); ++k) {
      ASSERT_EQ(plain.isAlive(TetId(k)), cached.isAlive(TetId(k)));
      if (!plain.isAlive(TetId(k))) continue;
      for (int i = 0; i < 4; ++i) ASSERT_EQ(plain.tetVertices(TetId(k))[i], cached.tetVertices(TetId(k))[i]);
      // The cache holds each live tet's sphere.
      const std::uint32_t* v = cached.tetVertices(TetId(k));
      const CachedSphere s = cachedSphere(cached.coords(VertexId(v[0])), cached.coords(VertexId(v[1])),
                                          cached.coords(VertexId(v[2])), cached.coords(VertexId(v[3])));
      if (!std::isnan(sphereRadius2(s))) {
        ASSERT_EQ(sphereRadius2(b.sphere(TetId(k))), sphereRadius2(s));
      }
    }
    ValidateOptions o;
    o.checkDelaunay = true;
    EXPECT_TRUE(validate(cached, o).empty());
    EXPECT_EQ(a.inSphereTests(), b.inSphereTests());
  }
}

TEST(Circumsphere, PowerTestImpliesVisibility) {
  // Two tets t = (f, a) and n = (f, b) on either side of face f. Whenever p is strictly
  // inside S_t, not strictly inside S_n, and a is certified outside S_n (the pair locally
  // Delaunay), p must see f from a's side: the argument of Inserter::visibleByPower.
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int used = 0, notLocallyDelaunay = 0;
  for (int k = 0; k < 200000; ++k) {
    double f[3][3], a[3], b[3], p[3];
    for (auto& v : f)
      for (double& x : v) x = u(rng);
    for (int i = 0; i < 3; ++i) a[i] = u(rng), b[i] = u(rng), p[i] = 1.5 * u(rng);
    const double sa = predicates::orient3d(f[0], f[1], f[2], a), sb = predicates::orient3d(f[0], f[1], f[2], b);
    if (sa == 0 || sb == 0 || (sa > 0) == (sb > 0)) continue;
    const CachedSphere sn = cachedSphere(f[0], f[1], f[2], b);
    const bool inT = predicates::insphere(f[0], f[1], f[2], a, p) * sa > 0;
    const bool inN = predicates::insphere(f[0], f[1], f[2], b, p) * sb > 0;
    if (sphereSide(sn, a) >= 0) {
      ++notLocallyDelaunay;
      continue;
    }
    if (!inT || inN) continue;
    ++used;
    // p on a's side of f.
    const double op = predicates::orient3d(f[0], f[1], f[2], p);
    ASSERT_TRUE(op != 0 && (op > 0) == (sa > 0)) << k;
  }
  EXPECT_GT(used, 1000);
  EXPECT_GT(notLocallyDelaunay, 1000);
}
