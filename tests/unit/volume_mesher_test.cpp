// Unit tests of the volume mesher's core (boundary mesh, boundary triangulation, recovery,
// carving, assembly) on hand-made solids, with the validators after every phase.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "mesher/volume/BoundaryMesh.h"
#include "mesher/volume/SolidMeshCache.h"
#include "mesher/volume/VolumeMesher.h"
#include "volume_test_models.h"

using namespace aniso;
using voltest::joined;

namespace {

std::string problems(const VolumeMeshResult& r) {
  std::string s;
  for (const SolidOutcome& o : r.solids)
    for (const VolumeProblem& p : o.problems) s += entityName(p.entity) + ": " + p.detail + "\n";
  return s;
}

VolumeMeshResult boundaryOnly(const voltest::SolidModel& m, int threads = 1) {
  VolumeMesherInput in;
  in.model = &m.model;
  in.surface = &m.surface;
  in.options.threads = threads;
  in.refine = false;
  in.improve = false;
  in.validate = true;
  in.quality = false;  // the hand-made faces have no geometry for a control space
  return meshVolumes(in);
}

double meshVolume(const VolumeMesh& vm) {
  double v = 0;
  for (const auto& t : vm.tets) {
    const Vec3 a = vm.nodes()[t[0]];
    v += (vm.nodes()[t[1]] - a).dot((vm.nodes()[t[2]] - a).cross(vm.nodes()[t[3]] - a)) / 6.0;
  }
  return v;
}

void expectMeshed(const voltest::SolidModel& m, const VolumeMeshResult& r) {
  ASSERT_TRUE(r.ok()) << problems(r);
  EXPECT_EQ(joined(r.mesh.validate()), "");
  EXPECT_NEAR(meshVolume(r.mesh), m.volume, 1e-12 * std::max(1.0, m.volume));
  // Every boundary triangle is the face of exactly one tetrahedron (validate() checks the
  // converse); the surface nodes come first with the same indices.
  EXPECT_EQ(r.mesh.nodes().size() >= m.surface.nodes.size(), true);
  for (std::size_t i = 0; i < m.surface.nodes.size(); ++i) ASSERT_EQ(r.mesh.nodes()[i], m.surface.nodes[i]);
}

}  // namespace

TEST(VolumeBoundaryMesh, CubeIsClosedAndOutward) {
  const voltest::SolidModel m = voltest::gridCube(3, false);
  const auto byFace = trianglesByFace(m.surface, static_cast<int>(m.model.faces.size()));
  const BoundaryMesh b = buildBoundaryMesh(m.model, m.surface, byFace, 0);
  EXPECT_EQ(joined(checkBoundaryMesh(b, m.surface)), "");
  EXPECT_EQ(b.triangles.size(), m.surface.triangles.size());
  EXPECT_NEAR(signedVolume(m.surface, b.triangles), 1.0, 1e-12);
  EXPECT_TRUE(b.flippedShells.empty());
}

TEST(VolumeBoundaryMesh, ReversedShellIsFlippedBySignedVolume) {
  voltest::SolidModel m = voltest::gridCube(2, false);
  for (FaceUse& u : m.model.shells[0].faces) u.reversed = true;  // every use says "inward"
  const auto byFace = trianglesByFace(m.surface, static_cast<int>(m.model.faces.size()));
  const BoundaryMesh b = buildBoundaryMesh(m.model, m.surface, byFace, 0);
  EXPECT_EQ(b.flippedShells.size(), 1u);
  EXPECT_NEAR(signedVolume(m.surface, b.triangles), 1.0, 1e-12);
}

TEST(VolumeBoundaryMesh, MisorientedFaceIsNamed) {
  voltest::SolidModel m = voltest::gridCube(2, false);
  m.model.shells[0].faces[3].reversed = true;  // face 4 taken the wrong way round
  const auto byFace = trianglesByFace(m.surface, static_cast<int>(m.model.faces.size()));
  const BoundaryMesh b = buildBoundaryMesh(m.model, m.surface, byFace, 0);
  const std::string msg = joined(checkBoundaryMesh(b, m.surface));
  EXPECT_NE(msg.find("not consistently oriented"), std::string::npos) << msg;
  EXPECT_NE(msg.find("4"), std::string::npos) << msg;
}

TEST(VolumeBoundaryMesh, OpenBoundaryIsNamedAndFailsTheSolid) {
  voltest::SolidModel m = voltest::gridCube(2, false);
  m.surface.triangles.pop_back();  // a hole in face 6
  m.surface.triangleFace.pop_back();
  const VolumeMeshResult r = boundaryOnly(m);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(problems(r).find("not closed"), std::string::npos) << problems(r);
  const std::string msg = problems(r);
  EXPECT_NE(msg.find("6", msg.find("on faces")), std::string::npos) << msg;
  EXPECT_TRUE(r.mesh.tets.empty());
}

TEST(VolumeMesher, CubeWithCoplanarCosphericalGrid) {
  for (const bool alternate : {false, true}) {
    const voltest::SolidModel m = voltest::gridCube(4, alternate);
    const VolumeMeshResult r = boundaryOnly(m);
    expectMeshed(m, r);
    EXPECT_EQ(r.solids[0].recovery.faces, static_cast<long long>(m.surface.triangles.size()));
  }
}

TEST(VolumeMesher, CubeWithCubicVoid) {
  const voltest::SolidModel m = voltest::cubeWithVoid(3, 0.4);
  const VolumeMeshResult r = boundaryOnly(m);
  expectMeshed(m, r);
  // No tetrahedron inside the void.
  for (const auto& t : r.mesh.tets) {
    Vec3 c(0, 0, 0);
    for (const int v : t) c += r.mesh.nodes()[v] / 4.0;
    EXPECT_FALSE((c.array() > 0.3 + 1e-9).all() && (c.array() < 0.7 - 1e-9).all());
  }
}

TEST(VolumeMesher, SchoenhardtPrismNeedsAnInteriorSteinerPoint) {
  const voltest::SolidModel m = voltest::schoenhardtPrism();
  const VolumeMeshResult r = boundaryOnly(m);
  expectMeshed(m, r);
  EXPECT_GE(r.recovery.steinerPoints, 1);
  EXPECT_GT(r.mesh.nodes().size(), m.surface.nodes.size());
  for (std::size_t i = m.surface.nodes.size(); i < r.mesh.nodes().size(); ++i) {
    EXPECT_EQ(r.mesh.surface.nodeOn[i].kind, NodeOn::Kind::Solid);
    // Strictly inside: above the bottom, below the top, inside the inscribed circle.
    const Vec3 p = r.mesh.nodes()[i];
    EXPECT_GT(p.z(), 0);
    EXPECT_LT(p.z(), 1);
    EXPECT_LT(std::hypot(p.x(), p.y()), 0.5);
  }
}

TEST(VolumeMesher, SameOutputForAnyThreadCount) {
  voltest::SolidBuilder b;
  const int s1 = b.addShell();
  b.box(s1, Vec3(0, 0, 0), 1.0, 3, false, true);
  const int s2 = b.addShell();
  b.box(s2, Vec3(2, 0, 0), 1.0, 2, false, false);
  b.model().solids.push_back({"A", s1, {}});
  b.model().solids.push_back({"B", s2, {}});
  const voltest::SolidModel m = b.done(2.0);
  const VolumeMeshResult r1 = boundaryOnly(m, 1), r2 = boundaryOnly(m, 2);
  expectMeshed(m, r1);
  EXPECT_EQ(r1.mesh.tets, r2.mesh.tets);
  EXPECT_EQ(r1.mesh.tetSolid, r2.mesh.tetSolid);
  EXPECT_EQ(r1.mesh.nodes(), r2.mesh.nodes());
}

namespace {

voltest::SolidModel twoBoxes(double xB) {
  voltest::SolidBuilder b;
  const int s1 = b.addShell();
  b.box(s1, Vec3(0, 0, 0), 1.0, 3, false, true);
  const int s2 = b.addShell();
  b.box(s2, Vec3(xB, 0, 0), 1.0, 2, false, false);
  b.model().solids.push_back({"A", s1, {}});
  b.model().solids.push_back({"B", s2, {}});
  return b.done(2.0);  // the volume of the two unit boxes
}

VolumeMeshResult boundaryOnlyCached(const voltest::SolidModel& m, SolidMeshCache& cache) {
  VolumeMesherInput in;
  in.model = &m.model;
  in.surface = &m.surface;
  in.refine = in.improve = in.quality = false;
  in.validate = true;
  in.cache = &cache;
  return meshVolumes(in);
}

}  // namespace

// SolidMeshCache.h: a solid whose boundary did not change is taken from the cache, one that
// changed is meshed again, and the result is the mesh made without the cache.
TEST(VolumeMesher, SolidMeshCacheKeepsUnchangedSolidsOnly) {
  const voltest::SolidModel m = twoBoxes(2.0);
  SolidMeshCache cache(m.model.solids.size());
  const VolumeMeshResult first = boundaryOnlyCached(m, cache);
  expectMeshed(m, first);
  EXPECT_EQ(first.solidsReused, 0);
  const VolumeMeshResult again = boundaryOnlyCached(m, cache);
  EXPECT_EQ(again.solidsReused, 2);
  EXPECT_EQ(again.mesh.tets, first.mesh.tets);
  EXPECT_EQ(again.mesh.nodes(), first.mesh.nodes());

  const voltest::SolidModel moved = twoBoxes(2.5);  // box B elsewhere, box A the same
  const VolumeMeshResult cached = boundaryOnlyCached(moved, cache);
  EXPECT_EQ(cached.solidsReused, 1);
  const VolumeMeshResult fresh = boundaryOnly(moved);
  expectMeshed(moved, cached);
  EXPECT_EQ(cached.mesh.tets, fresh.mesh.tets);
  EXPECT_EQ(cached.mesh.nodes(), fresh.mesh.nodes());
  EXPECT_NE(cached.mesh.nodes(), first.mesh.nodes());
}

namespace {

/// Solid 0: the slab [0,1]^2 x [0,0.05] (8 x 8 cells on each face: thinner than its
/// triangles); solid 1: the unit box on x = 1, z from 0.05, touching the slab along its
/// edge x = 1, z = 0.05 (same grid nodes there); solid 2: a unit box far away.
voltest::SolidModel slabWithNeighbours() {
  voltest::SolidBuilder b;
  const int slab = b.addShell();
  const double t = 0.05;
  const Vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, t), o(0, 0, 0);
  b.gridFace(slab, o, y, x, 8, false);      // z = 0
  b.gridFace(slab, o + z, x, y, 8, false);  // z = t
  b.gridFace(slab, o, x, z, 8, false);      // y = 0
  b.gridFace(slab, o + y, z, x, 8, false);  // y = 1
  b.gridFace(slab, o, z, y, 8, false);      // x = 0
  b.gridFace(slab, o + x, y, z, 8, false);  // x = 1
  const int near = b.addShell();
  b.box(near, Vec3(1, 0, t), 1.0, 8, false, false);
  const int far = b.addShell();
  b.box(far, Vec3(4, 0, 0), 1.0, 8, false, false);
  b.model().solids.push_back({"slab", slab, {}});
  b.model().solids.push_back({"near", near, {}});
  b.model().solids.push_back({"far", far, {}});
  return b.done(t + 2.0);
}

}  // namespace

// VolumeMesherInput::stopWhenThin: the thin solid stops, and so does the solid touching it
// (deferred: its boundary changes with the finer surface); the one far away is meshed, as
// it would be without stopWhenThin.
TEST(VolumeMesher, SolidsTouchingAThinOneWaitForTheFinerSurface) {
  const voltest::SolidModel m = slabWithNeighbours();
  VolumeMesherInput in;
  in.model = &m.model;
  in.surface = &m.surface;
  in.refine = in.improve = in.quality = false;
  in.validate = true;
  in.stopWhenThin = true;
  const VolumeMeshResult round = meshVolumes(in);
  ASSERT_EQ(round.solids.size(), 3u);
  EXPECT_FALSE(round.thin.empty());
  for (const ThinSpot& spot : round.thin) EXPECT_EQ(spot.solid, 0);
  EXPECT_EQ(round.solidsDeferred, 1);
  EXPECT_EQ(round.solids[0].tets, 0u);
  EXPECT_EQ(round.solids[1].tets, 0u);
  EXPECT_EQ(round.solids[1].status, SolidOutcome::Status::Ok);
  EXPECT_GT(round.solids[2].tets, 0u);

  in.stopWhenThin = false;
  const VolumeMeshResult whole = meshVolumes(in);
  expectMeshed(m, whole);
  EXPECT_EQ(whole.solidsDeferred, 0);
  EXPECT_EQ(whole.solids[2].tets, round.solids[2].tets);
  EXPECT_GT(whole.solids[1].tets, 0u);
}
