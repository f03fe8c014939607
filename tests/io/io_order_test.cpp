// Node orders of the formats and the Abaqus face numbering, checked geometrically on a
// tetrahedron whose mid-edge nodes are built from the contract's edge table.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <set>

#include "io/ElementOrder.h"
#include "mesher/volume/VolumeMesh.h"

using namespace aniso;
using namespace aniso::io;

namespace {

/// A positively oriented tetrahedron with its 10 nodes in canonical order.
std::array<Vec3, 10> tet10() {
  std::array<Vec3, 10> p;
  p[0] = Vec3(0, 0, 0);
  p[1] = Vec3(1, 0, 0);
  p[2] = Vec3(0.2, 1, 0);
  p[3] = Vec3(0.3, 0.2, 1);
  for (int k = 0; k < 6; ++k) p[4 + k] = 0.5 * (p[VolumeMesh::kTetEdges[k][0]] + p[VolumeMesh::kTetEdges[k][1]]);
  return p;
}

/// Node `written` of a format is the midpoint of corners (a, b) of the format's own numbering.
void expectMid(const std::array<Vec3, 10>& p, const int* order, int written, int a, int b) {
  const Vec3 mid = 0.5 * (p[order[a]] + p[order[b]]);
  EXPECT_LT((p[order[written]] - mid).norm(), 1e-15) << "node " << written << " should be on edge " << a << "-" << b;
}

}  // namespace

TEST(IoOrder, GmshTet10HasEdges32And31Last) {
  const auto p = tet10();
  const int* o = order::kGmshTet10.data();
  // Gmsh manual: 4:(0,1) 5:(1,2) 6:(2,0) 7:(3,0) 8:(3,2) 9:(3,1)
  const int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
  for (int k = 0; k < 6; ++k) expectMid(p, o, 4 + k, edges[k][0], edges[k][1]);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(o[k], k);
}

TEST(IoOrder, AbaqusC3D10IsCanonical) {
  const auto p = tet10();
  const int* o = order::kIdentity.data();
  // Abaqus manual (1-based): 5:(1,2) 6:(2,3) 7:(3,1) 8:(1,4) 9:(2,4) 10:(3,4)
  const int edges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  for (int k = 0; k < 6; ++k) expectMid(p, o, 4 + k, edges[k][0], edges[k][1]);
}

TEST(IoOrder, UnvTet10GoesRoundTheElement) {
  const auto p = tet10();
  std::array<Vec3, 10> w;  // as written
  for (int k = 0; k < 10; ++k) w[k] = p[order::kUnvTet10[k]];
  // I-DEAS 118: c1 m12 c2 m23 c3 m31 m14 m24 m34 c4
  EXPECT_EQ(w[0], p[0]);
  EXPECT_EQ(w[2], p[1]);
  EXPECT_EQ(w[4], p[2]);
  EXPECT_EQ(w[9], p[3]);
  EXPECT_LT((w[1] - 0.5 * (w[0] + w[2])).norm(), 1e-15);
  EXPECT_LT((w[3] - 0.5 * (w[2] + w[4])).norm(), 1e-15);
  EXPECT_LT((w[5] - 0.5 * (w[4] + w[0])).norm(), 1e-15);
  EXPECT_LT((w[6] - 0.5 * (w[0] + w[9])).norm(), 1e-15);
  EXPECT_LT((w[7] - 0.5 * (w[2] + w[9])).norm(), 1e-15);
  EXPECT_LT((w[8] - 0.5 * (w[4] + w[9])).norm(), 1e-15);
}

TEST(IoOrder, UnvTri6AndQuad8AlternateCornersAndMids) {
  // canonical tri6: c0 c1 c2 m01 m12 m20 -> c0 m01 c1 m12 c2 m20
  const std::array<int, 6> tri = {0, 3, 1, 4, 2, 5};
  EXPECT_EQ(order::kUnvTri6, tri);
  const std::array<int, 8> quad = {0, 4, 1, 5, 2, 6, 3, 7};
  EXPECT_EQ(order::kUnvQuad8, quad);
}

TEST(IoOrder, AbaqusFacesAreTheDocumentedTriples) {
  // S1 = 1-2-3, S2 = 1-4-2, S3 = 2-4-3, S4 = 3-4-1 (1-based)
  const int doc[4][3] = {{1, 2, 3}, {1, 4, 2}, {2, 4, 3}, {3, 4, 1}};
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 3; ++j) EXPECT_EQ(order::kAbaqusTetFaces[k][j] + 1, doc[k][j]);
}

TEST(IoOrder, AbaqusFaceNormalsPointOutOfThePositiveTet) {
  const auto p = tet10();
  ASSERT_GT((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])), 0);
  std::set<int> opposite;
  for (int k = 0; k < 4; ++k) {
    const int* f = order::kAbaqusTetFaces[k];
    int other = 0 + 1 + 2 + 3 - f[0] - f[1] - f[2];
    opposite.insert(other);
    // Abaqus lists each face so that its right-hand normal points inward: the outward
    // normal is the reverse.
    const Vec3 outward = -(p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]);
    const Vec3 centre = (p[f[0]] + p[f[1]] + p[f[2]]) / 3;
    EXPECT_GT(outward.dot(centre - p[other]), 0) << "S" << k + 1;
  }
  EXPECT_EQ(opposite.size(), 4u);  // four distinct faces
}

TEST(IoOrder, AbaqusFaceOfFindsEveryPermutation) {
  const std::array<int, 4> tet = {10, 20, 30, 40};
  EXPECT_EQ(order::abaqusFaceOf(tet, 30, 10, 20), 1);
  EXPECT_EQ(order::abaqusFaceOf(tet, 40, 20, 10), 2);
  EXPECT_EQ(order::abaqusFaceOf(tet, 20, 30, 40), 3);
  EXPECT_EQ(order::abaqusFaceOf(tet, 10, 40, 30), 4);
  EXPECT_EQ(order::abaqusFaceOf(tet, 10, 20, 50), 0);
}
