// Unit tests of the 3D kernel's flips (T23, T32, T44) and of the edge ring iteration.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>

#include "mesher/core/Error.h"
#include "mesher/delaunay3d/Delaunay3d.h"
#include "mesher/delaunay3d/EdgeRing.h"
#include "mesher/delaunay3d/FlipT23.h"
#include "mesher/delaunay3d/FlipT32.h"
#include "mesher/delaunay3d/FlipT44.h"
#include "mesher/delaunay3d/Inserter.h"
#include "mesher/delaunay3d/LocalRetriangulation.h"
#include "mesher/delaunay3d/RemoveTets.h"
#include "mesher/delaunay3d/Validate.h"

using namespace aniso;
using namespace aniso::del3d;

namespace {

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += x + "\n";
  return s;
}

using Quad = std::array<std::uint32_t, 4>;

// Builds a mesh from points and tets (each made positive by swapping if needed), linking
// faces with equal vertex triples.
TetMesh meshFrom(const std::vector<Vec3>& pts, const std::vector<Quad>& tets) {
  TetMesh mesh;
  for (const Vec3& p : pts) mesh.addVertex(p);
  std::vector<TetId> ids;
  for (Quad q : tets) {
    std::array<VertexId, 4> v = {VertexId(q[0]), VertexId(q[1]), VertexId(q[2]), VertexId(q[3])};
    if (orientation(mesh, v) < 0) std::swap(v[0], v[1]);
    ids.push_back(mesh.createTet(v[0], v[1], v[2], v[3]));
    for (const VertexId x : v) mesh.setVertexTet(x, ids.back());
  }
  auto key = [&](TetId t, int i) {
    std::array<std::uint32_t, 3> f;
    for (int m = 0; m < 3; ++m) f[m] = mesh.tetVertices(t)[kFaceVertex[i][m]];
    std::sort(f.begin(), f.end());
    return f;
  };
  for (std::size_t a = 0; a < ids.size(); ++a)
    for (std::size_t b = a + 1; b < ids.size(); ++b)
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          if (key(ids[a], i) == key(ids[b], j)) mesh.link(ids[a], i, ids[b], j);
  return mesh;
}

std::set<std::set<std::uint32_t>> tetSets(const TetMesh& mesh) {
  std::set<std::set<std::uint32_t>> out;
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k)
    if (mesh.isAlive(TetId(k))) {
      const std::uint32_t* v = mesh.tetVertices(TetId(k));
      out.insert({v[0], v[1], v[2], v[3]});
    }
  return out;
}

// Two tets sharing face (0,1,2) with apexes 3 (above) and 4 (below), plus an outer tet on
// a face of each so that outer adjacency and constrained bits are exercised.
std::vector<Vec3> bipyramidPoints() {
  return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.3, 0.3, 1), Vec3(0.2, 0.3, -1),
          Vec3(1, 1, 1), Vec3(-1, -1, -1)};
}

}  // namespace

TEST(Delaunay3dFlips, T23ThenT32ReturnsTheOriginal) {
  TetMesh mesh = meshFrom(bipyramidPoints(), {{0, 1, 2, 3}, {0, 1, 2, 4}, {1, 2, 3, 5}, {0, 1, 4, 6}});
  ASSERT_TRUE(validate(mesh).empty()) << joined(validate(mesh));
  const auto original = tetSets(mesh);
  // Constrain an outer face of the bipyramid; it must survive both flips.
  TetId t0;
  int shared = -1;
  for (std::uint32_t k = 0; k < 4; ++k) {
    const std::uint32_t* v = mesh.tetVertices(TetId(k));
    if (std::set<std::uint32_t>{v[0], v[1], v[2], v[3]} == std::set<std::uint32_t>{0, 1, 2, 3}) {
      t0 = TetId(k);
      shared = mesh.localIndex(t0, VertexId(3));
    }
  }
  ASSERT_TRUE(t0.valid());
  const int outerFace = mesh.localIndex(t0, VertexId(0));  // face (1,2,3), shared with tet {1,2,3,5}
  mesh.setConstrained(t0, outerFace, true);

  Flip23Plan plan;
  ASSERT_TRUE(canFlip23(mesh, t0, shared, &plan));
  const std::array<TetId, 3> three = flip23(mesh, plan);
  EXPECT_EQ(mesh.numTets(), 5u);
  EXPECT_TRUE(validate(mesh).empty()) << joined(validate(mesh));
  for (const TetId t : three) {
    EXPECT_GE(mesh.localIndex(t, VertexId(3)), 0);
    EXPECT_GE(mesh.localIndex(t, VertexId(4)), 0);
  }
  // The constrained face (1,2,3) is still constrained.
  bool found = false;
  for (const TetId t : three) {
    const int i = mesh.localIndex(t, VertexId(4));
    if (mesh.localIndex(t, VertexId(0)) < 0) {
      found = true;
      EXPECT_TRUE(mesh.isConstrained(t, i));
    }
  }
  EXPECT_TRUE(found);

  // Edge (3,4) now has exactly three tets: flip it back.
  const TetId t = three[0];
  Flip32Plan back;
  ASSERT_TRUE(canFlip32(mesh, t, mesh.localIndex(t, VertexId(3)), mesh.localIndex(t, VertexId(4)), &back));
  flip32(mesh, back);
  EXPECT_TRUE(validate(mesh).empty()) << joined(validate(mesh));
  EXPECT_EQ(tetSets(mesh), original);
  EXPECT_EQ(mesh.numTets(), 4u);
}

TEST(Delaunay3dFlips, IllegalFlipsAreRejected) {
  // Apex 4 below but outside the prism over triangle (0,1,2): segment 3-4 misses it.
  std::vector<Vec3> pts = bipyramidPoints();
  pts[4] = Vec3(2, 2, -1);
  TetMesh mesh = meshFrom(pts, {{0, 1, 2, 3}, {0, 1, 2, 4}});
  ASSERT_TRUE(validate(mesh).empty());
  const TetId t(0);
  const int f = mesh.localIndex(t, VertexId(3));
  EXPECT_FALSE(canFlip23(mesh, t, f));
  // A hull face and a constrained face cannot flip either.
  EXPECT_FALSE(canFlip23(mesh, t, mesh.localIndex(t, VertexId(0))));
  TetMesh ok = meshFrom(bipyramidPoints(), {{0, 1, 2, 3}, {0, 1, 2, 4}});
  const int g = ok.localIndex(TetId(0), VertexId(3));
  EXPECT_TRUE(canFlip23(ok, TetId(0), g));
  ok.setConstrained(TetId(0), g, true);
  EXPECT_FALSE(canFlip23(ok, TetId(0), g));
  // T32 needs exactly three tets around the edge.
  EXPECT_FALSE(canFlip32(ok, TetId(0), 0, 1));
}

TEST(Delaunay3dFlips, T44OnAnOctahedron) {
  // Edge (0,1) vertical, square ring 2..5 in the plane z = 0.
  const std::vector<Vec3> pts = {Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(1, 0, 0),
                                 Vec3(0, 1, 0),  Vec3(-1, 0, 0), Vec3(0, -1, 0)};
  TetMesh mesh = meshFrom(pts, {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 1, 4, 5}, {0, 1, 5, 2}});
  ASSERT_TRUE(validate(mesh).empty()) << joined(validate(mesh));
  const auto original = tetSets(mesh);
  const TetId t(0);
  const int i = mesh.localIndex(t, VertexId(0)), j = mesh.localIndex(t, VertexId(1));
  // 4 tets: T32 impossible; T44 to either diagonal is legal.
  EXPECT_FALSE(canFlip32(mesh, t, i, j));
  Flip44Plan plan;
  ASSERT_TRUE(canFlip44(mesh, t, i, j, 0, &plan));
  ASSERT_TRUE(canFlip44(mesh, t, i, j, 1));
  const auto four = flip44(mesh, plan);
  EXPECT_TRUE(validate(mesh).empty()) << joined(validate(mesh));
  EXPECT_EQ(mesh.numTets(), 4u);
  // The new edge is a diagonal of the square; every new tet contains it.
  std::set<std::uint32_t> common = {0, 1, 2, 3, 4, 5};
  for (const TetId n : four) {
    std::set<std::uint32_t> keep;
    for (int m = 0; m < 4; ++m)
      if (common.count(mesh.vertex(n, m).index)) keep.insert(mesh.vertex(n, m).index);
    common = keep;
  }
  ASSERT_EQ(common.size(), 2u);
  EXPECT_FALSE(common.count(0) || common.count(1));
  // Flip back around the new edge: one of its two diagonals is (0,1).
  const VertexId d0(*common.begin()), d1(*common.rbegin());
  const TetId u = four[0];
  bool restored = false;
  for (int diag = 0; diag < 2 && !restored; ++diag) {
    Flip44Plan p2;
    if (!canFlip44(mesh, u, mesh.localIndex(u, d0), mesh.localIndex(u, d1), diag, &p2)) continue;
    TetMesh copy = mesh;
    flip44(copy, p2);
    if (tetSets(copy) == original) {
      restored = true;
      EXPECT_TRUE(validate(copy).empty());
    }
  }
  EXPECT_TRUE(restored);
  // A ring whose quadrilateral is reflex at c0 = (0.5, 0, 0): only the diagonal from the
  // reflex vertex, (0.5,0,0)-(-1,0,0), lies inside; the other one, x = 1, does not.
  const std::vector<Vec3> bent = {Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(0.5, 0, 0),
                                  Vec3(1, 1, 0),  Vec3(-1, 0, 0), Vec3(1, -1, 0)};
  TetMesh m2 = meshFrom(bent, {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 1, 4, 5}, {0, 1, 5, 2}});
  ASSERT_TRUE(validate(m2).empty()) << joined(validate(m2));
  const int a = m2.localIndex(TetId(0), VertexId(0)), b = m2.localIndex(TetId(0), VertexId(1));
  const bool diag0 = canFlip44(m2, TetId(0), a, b, 0), diag1 = canFlip44(m2, TetId(0), a, b, 1);
  EXPECT_NE(diag0, diag1);
  Flip44Plan p3;
  ASSERT_TRUE(canFlip44(m2, TetId(0), a, b, diag0 ? 0 : 1, &p3));
  const auto around = flip44(m2, p3);
  EXPECT_TRUE(validate(m2).empty());
  for (const TetId n : around) {
    EXPECT_GE(m2.localIndex(n, VertexId(2)), 0);
    EXPECT_GE(m2.localIndex(n, VertexId(4)), 0);
  }
}

TEST(Delaunay3dFlips, EdgeRingMatchesBruteForce) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> pts(500);
  for (Vec3& p : pts) p = Vec3(u(rng), u(rng), u(rng));
  TetMesh mesh;
  const DelaunayResult res = buildDelaunay(mesh, pts);
  removeTets(mesh, tetsTouching(mesh, res.box.corners));  // makes hull edges (open rings)
  ASSERT_TRUE(validate(mesh).empty());
  EdgeRing ring;
  std::size_t open = 0, closed = 0;
  for (std::uint32_t k = 0; k < mesh.tetSlots(); k += 3) {
    const TetId t(k);
    if (!mesh.isAlive(t)) continue;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        edgeRing(mesh, t, i, j, ring);
        std::set<std::uint32_t> brute;
        for (std::uint32_t q = 0; q < mesh.tetSlots(); ++q)
          if (mesh.isAlive(TetId(q)) && mesh.localIndex(TetId(q), ring.a) >= 0 && mesh.localIndex(TetId(q), ring.b) >= 0)
            brute.insert(q);
        std::set<std::uint32_t> got;
        for (const TetId r : ring.tets) got.insert(r.index);
        ASSERT_EQ(got, brute);
        ASSERT_EQ(got.size(), ring.tets.size());
        ASSERT_EQ(ring.apex.size(), ring.tets.size() + (ring.closed ? 0 : 1));
        const std::size_t n = ring.tets.size();
        for (std::size_t m = 0; m < n; ++m) {
          const TetId r = ring.tets[m];
          EXPECT_GE(mesh.localIndex(r, ring.apex[m]), 0);
          EXPECT_GE(mesh.localIndex(r, ring.apex[(m + 1) % ring.apex.size()]), 0);
          if (ring.closed || m + 1 < n) {
            const TetId next = ring.tets[(m + 1) % n];
            EXPECT_EQ(mesh.neighbour(r, mesh.localIndex(r, ring.apex[m])), next);
          }
        }
        (ring.closed ? closed : open)++;
        if (ring.closed && n <= 8) {
          std::array<TetId, 8> tets;
          std::array<VertexId, 8> apex;
          EXPECT_EQ(closedEdgeRing(mesh, t, i, j, std::span(tets).first(n), std::span(apex).first(n)),
                    static_cast<int>(n));
        }
      }
  }
  EXPECT_GT(open, 0u);
  EXPECT_GT(closed, 0u);
}

TEST(Delaunay3dFlips, RandomLegalFlipsKeepTheMeshValid) {
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> pts(300);
  for (Vec3& p : pts) p = Vec3(u(rng), u(rng), u(rng));
  TetMesh mesh;
  buildDelaunay(mesh, pts);
  // Some constrained faces that flips must keep.
  for (std::uint32_t k = 0; k < mesh.tetSlots(); k += 17)
    if (mesh.isAlive(TetId(k))) mesh.setConstrained(TetId(k), static_cast<int>(k % 4), true);
  std::size_t f23 = 0, f32 = 0, f44 = 0;
  for (int it = 0; it < 3000; ++it) {
    const TetId t(static_cast<std::uint32_t>(rng() % mesh.tetSlots()));
    if (!mesh.isAlive(t)) continue;
    const int i = static_cast<int>(rng() % 4);
    int j = static_cast<int>(rng() % 3);
    if (j >= i) ++j;
    const std::size_t constrainedBefore = [&] {
      std::size_t c = 0;
      for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k)
        if (mesh.isAlive(TetId(k)))
          for (int f = 0; f < 4; ++f) c += mesh.isConstrained(TetId(k), f);
      return c;
    }();
    Flip23Plan p23;
    Flip32Plan p32;
    Flip44Plan p44;
    if (it % 3 == 0 && canFlip23(mesh, t, i, &p23)) {
      flip23(mesh, p23);
      ++f23;
    } else if (it % 3 == 1 && canFlip32(mesh, t, i, j, &p32)) {
      flip32(mesh, p32);
      ++f32;
    } else if (it % 3 == 2 && canFlip44(mesh, t, i, j, it % 2, &p44)) {
      flip44(mesh, p44);
      ++f44;
    } else {
      continue;
    }
    const auto problems = validate(mesh);
    ASSERT_TRUE(problems.empty()) << it << "\n" << joined(problems);
    std::size_t constrainedAfter = 0;
    for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k)
      if (mesh.isAlive(TetId(k)))
        for (int f = 0; f < 4; ++f) constrainedAfter += mesh.isConstrained(TetId(k), f);
    ASSERT_EQ(constrainedAfter, constrainedBefore);
  }
  EXPECT_GT(f23, 10u);
  EXPECT_GT(f32, 10u);
  EXPECT_GT(f44 + f32 + f23, 30u);
}

TEST(Delaunay3dFlips, ReplaceTetsRejectsMismatchedBoundaries) {
  TetMesh mesh = meshFrom(bipyramidPoints(), {{0, 1, 2, 3}, {0, 1, 2, 4}});
  const auto before = tetSets(mesh);
  const std::array<TetId, 2> old = {TetId(0), TetId(1)};
  std::array<VertexId, 4> v = {VertexId(0), VertexId(1), VertexId(2), VertexId(3)};
  if (orientation(mesh, v) < 0) std::swap(v[0], v[1]);
  const std::array<std::array<VertexId, 4>, 1> one = {v};
  std::array<TetId, 1> out;
  EXPECT_THROW(replaceTets(mesh, old, one, out), MeshingError);
  EXPECT_EQ(tetSets(mesh), before);
  EXPECT_TRUE(validate(mesh).empty());
}

TEST(Delaunay3dFlips, InsertionIntoAFlippedNonDelaunayMeshStaysValid) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> pts(400);
  for (Vec3& p : pts) p = Vec3(u(rng), u(rng), u(rng));
  TetMesh mesh;
  buildDelaunay(mesh, std::span(pts).first(200));
  EXPECT_TRUE(mesh.certifiedDelaunay());
  std::size_t flips = 0;
  for (int it = 0; it < 4000; ++it) {
    const TetId t(static_cast<std::uint32_t>(rng() % mesh.tetSlots()));
    Flip23Plan p;
    if (mesh.isAlive(t) && canFlip23(mesh, t, static_cast<int>(rng() % 4), &p)) {
      flip23(mesh, p);
      ++flips;
    }
  }
  ASSERT_GT(flips, 100u);
  EXPECT_FALSE(mesh.certifiedDelaunay());
  ValidateOptions d;
  d.checkDelaunay = true;
  d.maxProblems = 100000;
  ASSERT_GT(validate(mesh, d).size(), 50u);  // far from Delaunay now
  Inserter ins(mesh);
  std::size_t inserted = 0;
  for (std::size_t k = 200; k < pts.size(); ++k) {
    const InsertResult r = ins.insert(pts[k]);
    ASSERT_NE(r.status, InsertStatus::Outside);
    ASSERT_NE(r.status, InsertStatus::Duplicate);
    inserted += r.status == InsertStatus::Inserted;
    const auto problems = validate(mesh);
    ASSERT_TRUE(problems.empty()) << k << "\n" << joined(problems);
  }
  EXPECT_GT(inserted, 150u);
  // Every vertex that was in the mesh is still in some tet.
  for (std::uint32_t v = 0; v < mesh.numVertices(); ++v) {
    const TetId t = mesh.vertexTet(VertexId(v));
    ASSERT_TRUE(t.valid()) << v;
    ASSERT_GE(mesh.localIndex(t, VertexId(v)), 0);
  }
}
