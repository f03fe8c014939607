// Tests of TetMesh::renumber (mesher/delaunay3d/TetMesh.h): the same tetrahedralization
// (geometry, adjacency, constrained faces) under new vertex and tet numbers, free slots
// dropped, bad permutations refused without a change.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>

#include "mesher/core/Error.h"
#include "mesher/delaunay3d/EnclosingBox.h"
#include "mesher/delaunay3d/Inserter.h"
#include "mesher/delaunay3d/RemoveTets.h"
#include "mesher/delaunay3d/Validate.h"

using namespace aniso;
using namespace aniso::del3d;

namespace {

using Corners = std::array<std::array<double, 3>, 4>;

// Every live tet as its sorted corner coordinates, with the constrained bits of its faces
// keyed by the opposite corner.
std::set<std::pair<Corners, std::array<bool, 4>>> geometry(const TetMesh& mesh) {
  std::set<std::pair<Corners, std::array<bool, 4>>> out;
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k) {
    const TetId t(k);
    if (!mesh.isAlive(t)) continue;
    std::array<std::pair<std::array<double, 3>, bool>, 4> c;
    for (int i = 0; i < 4; ++i) {
      const Vec3 p = mesh.point(mesh.vertex(t, i));
      c[i] = {{p.x(), p.y(), p.z()}, mesh.isConstrained(t, i)};
    }
    std::sort(c.begin(), c.end());
    Corners x;
    std::array<bool, 4> f;
    for (int i = 0; i < 4; ++i) x[i] = c[i].first, f[i] = c[i].second;
    out.insert({x, f});
  }
  return out;
}

TetMesh randomMesh() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  TetMesh mesh;
  Box3 b;
  b.add(Vec3(0, 0, 0));
  b.add(Vec3(1, 1, 1));
  const EnclosingBox box = createEnclosingBox(mesh, b);
  Inserter ins(mesh);
  for (int k = 0; k < 400; ++k) EXPECT_EQ(ins.insert(Vec3(u(rng), u(rng), u(rng))).status, InsertStatus::Inserted);
  // free slots (and a hull) as after carving: the tets at the box corners removed
  removeTets(mesh, tetsTouching(mesh, box.corners));
  // a constrained face, so the bits are checked too
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k)
    if (mesh.isAlive(TetId(k)) && mesh.neighbour(TetId(k), 0).valid()) {
      mesh.setConstrained(TetId(k), 0, true);
      break;
    }
  return mesh;
}

TEST(Delaunay3dRenumber, ReversedNumbersKeepTheMesh) {
  TetMesh mesh = randomMesh();
  ASSERT_GT(mesh.tetSlots(), mesh.numTets());  // the insertions left free slots
  const auto before = geometry(mesh);
  const std::size_t nt = mesh.numTets();
  std::vector<std::uint32_t> newVertex(mesh.numVertices()), newTet(mesh.tetSlots(), kNone);
  for (std::size_t v = 0; v < newVertex.size(); ++v) newVertex[v] = static_cast<std::uint32_t>(newVertex.size() - 1 - v);
  std::uint32_t next = static_cast<std::uint32_t>(nt);
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k)
    if (mesh.isAlive(TetId(k))) newTet[k] = --next;
  const Vec3 p0 = mesh.point(VertexId(0));
  mesh.renumber(newVertex, newTet);
  EXPECT_EQ(mesh.numTets(), nt);
  EXPECT_EQ(mesh.tetSlots(), nt);  // free slots dropped
  EXPECT_EQ(mesh.freeHead(), kNone);
  EXPECT_EQ(mesh.point(VertexId(newVertex[0])), p0);
  const auto problems = validate(mesh);
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_EQ(geometry(mesh), before);
  // The renumbered mesh still takes insertions.
  Inserter ins(mesh);
  EXPECT_EQ(ins.insert(Vec3(0.5, 0.25, 0.75)).status, InsertStatus::Inserted);
  EXPECT_TRUE(validate(mesh).empty());
}

TEST(Delaunay3dRenumber, BadPermutationsAreRefused) {
  TetMesh mesh = randomMesh();
  const auto before = geometry(mesh);
  std::vector<std::uint32_t> newVertex(mesh.numVertices()), newTet(mesh.tetSlots(), kNone);
  for (std::size_t v = 0; v < newVertex.size(); ++v) newVertex[v] = static_cast<std::uint32_t>(v);
  std::uint32_t next = 0;
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k)
    if (mesh.isAlive(TetId(k))) newTet[k] = next++;
  std::vector<std::uint32_t> twice = newVertex;
  twice[1] = 0;
  EXPECT_THROW(mesh.renumber(twice, newTet), MeshingError);
  std::vector<std::uint32_t> freeUsed = newTet;
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k)
    if (!mesh.isAlive(TetId(k))) {
      freeUsed[k] = 0;
      break;
    }
  EXPECT_THROW(mesh.renumber(newVertex, freeUsed), MeshingError);
  EXPECT_THROW(mesh.renumber(newVertex, std::vector<std::uint32_t>(3, 0)), MeshingError);
  EXPECT_EQ(geometry(mesh), before);
  EXPECT_TRUE(validate(mesh).empty());
}

}  // namespace
