// The volume mesher's last resort when recovery leaves boundary entities out
// (CarveAroundHoles.h): tets classified one by one, the holes closed by patch faces, the
// solid kept and degraded; refused when the volume would be off.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "mesher/delaunay3d/FlipT23.h"
#include "mesher/volume/BoundaryMesh.h"
#include "mesher/volume/BoundaryRecovery.h"
#include "mesher/volume/BoundaryTriangulation.h"
#include "mesher/volume/CarveAroundHoles.h"
#include "mesher/volume/MeshQueries.h"
#include "mesher/volume/RayParity.h"
#include "mesher/volume/VolumeMesher.h"
#include "volume_test_models.h"

using namespace aniso;
using voltest::joined;

namespace {

/// A recovered cube whose boundary triangle `*removed` was then flipped away (T23 through
/// it, its constrained bit cleared first): recovery "failed" on exactly that triangle.
struct CubeWithHole {
  voltest::SolidModel m = voltest::gridCube(8, false);
  BoundaryMesh b;
  BoundaryTriangulation bt;
  std::size_t removed = 0;
};

bool makeHole(CubeWithHole& c) {
  const auto byFace = trianglesByFace(c.m.surface, static_cast<int>(c.m.model.faces.size()));
  c.b = buildBoundaryMesh(c.m.model, c.m.surface, byFace, 0);
  c.bt = triangulateBoundary(c.m.surface, c.b);
  if (!recoverBoundary(c.bt).left.empty()) return false;
  del3d::TetMesh& mesh = c.bt.tets.mesh;
  std::vector<del3d::TetId> star;
  for (std::size_t t = 0; t < c.bt.boundary.triangles.size(); ++t) {
    const auto& tri = c.bt.boundary.triangles[t];
    const volume::FaceHandle h = volume::findFace(mesh, tri[0], tri[1], tri[2], star);
    if (!h.valid()) return false;
    mesh.setConstrained(h.tet, h.face, false);
    del3d::Flip23Plan plan;
    if (del3d::canFlip23(mesh, h.tet, h.face, &plan)) {
      del3d::flip23(mesh, plan);
      c.removed = t;
      return true;
    }
    mesh.setConstrained(h.tet, h.face, true);
  }
  return false;
}

}  // namespace

TEST(CarveAroundHoles, AMissingTriangleIsClosedByPatchFaces) {
  CubeWithHole c;
  ASSERT_TRUE(makeHole(c));
  const HoleCarving hc = carveAroundHoles(c.bt.tets, c.bt.boundary, c.bt.box);
  ASSERT_EQ(joined(hc.problems), "");
  EXPECT_EQ(hc.notFound, 1u);
  ASSERT_FALSE(hc.missing.empty());
  EXPECT_EQ(hc.missing.front() <= c.removed && c.removed <= hc.missing.back(), true);
  EXPECT_NEAR(hc.enclosedVolume, 1.0, 1e-12);
  EXPECT_NEAR(hc.keptVolume, 1.0, kHoleVolumeTolerance);
  EXPECT_GE(hc.patchFaces, 1u);
  EXPECT_GT(hc.patchArea, 0.0);
  // the invariants hold with the triangles kept: patch faces on the hull and constrained
  std::vector<std::array<int, 3>> kept;
  for (std::size_t t = 0; t < c.b.triangles.size(); ++t)
    if (std::find(hc.missing.begin(), hc.missing.end(), t) == hc.missing.end()) kept.push_back(c.b.triangles[t]);
  EXPECT_EQ(joined(validateSolidTetMesh(c.bt.tets, kept)), "");
  // the patch's vertices are fixed
  for (const auto& f : c.bt.tets.patchFaces)
    for (const std::uint32_t v : f) EXPECT_TRUE(c.bt.tets.isFixed(del3d::VertexId(v)));
}

TEST(CarveAroundHoles, PresentBoundaryGivesTheSameTetsAsCarving) {
  CubeWithHole c;
  const auto byFace = trianglesByFace(c.m.surface, static_cast<int>(c.m.model.faces.size()));
  c.b = buildBoundaryMesh(c.m.model, c.m.surface, byFace, 0);
  c.bt = triangulateBoundary(c.m.surface, c.b);
  ASSERT_TRUE(recoverBoundary(c.bt).left.empty());
  const HoleCarving hc = carveAroundHoles(c.bt.tets, c.bt.boundary, c.bt.box);
  ASSERT_EQ(joined(hc.problems), "");
  EXPECT_TRUE(hc.missing.empty());
  EXPECT_EQ(hc.patchFaces, 0u);
  EXPECT_NEAR(hc.keptVolume, 1.0, 1e-12);
  EXPECT_EQ(joined(validateSolidTetMesh(c.bt.tets, c.b.triangles)), "");
}

namespace {

/// Schönhardt's prism with recovery by flips only and no split round: its reflex
/// diagonals stay missing, and the last resort decides.
VolumeMeshResult flipsOnly(const voltest::SolidModel& m) {
  VolumeMesherInput in;
  in.model = &m.model;
  in.surface = &m.surface;
  in.options.threads = 1;
  in.refine = false;
  in.improve = false;
  in.validate = true;
  in.quality = false;
  in.recovery.interiorPoints = false;
  in.maxSplitRounds = 0;
  return meshVolumes(in);
}

bool hasCode(const SolidOutcome& o, const std::string& code, Severity severity) {
  for (const Problem& p : o.problems)
    if (p.code == code && p.severity == severity) return true;
  return false;
}

}  // namespace

TEST(VolumeMesher, UnrecoveredSolidFarFromItsVolumeIsRefused) {
  const voltest::SolidModel m = voltest::schoenhardtPrism(1.0, 0.5);
  const VolumeMeshResult r = flipsOnly(m);
  ASSERT_EQ(r.solids.size(), 1u);
  EXPECT_EQ(r.solids[0].status, SolidOutcome::Status::Failed);
  EXPECT_TRUE(hasCode(r.solids[0], "holes-refused", Severity::Note));
  EXPECT_TRUE(hasCode(r.solids[0], "solid-mesh", Severity::Failed));
  EXPECT_TRUE(r.mesh.tets.empty());
  EXPECT_EQ(r.solidsWithHoles, 0);
}

TEST(VolumeMesher, UnrecoveredSolidIsMeshedAroundItsHoles) {
  // nearly a prism: the tets of its six nodes enclose its volume within 0.5 %
  const voltest::SolidModel m = voltest::schoenhardtPrism(1.0, 0.01);
  const VolumeMeshResult r = flipsOnly(m);
  ASSERT_EQ(r.solids.size(), 1u);
  EXPECT_TRUE(r.ok());
  EXPECT_EQ(r.solids[0].status, SolidOutcome::Status::Ok);
  EXPECT_TRUE(hasCode(r.solids[0], "recovery-holes", Severity::Degraded));
  EXPECT_FALSE(hasCode(r.solids[0], "solid-mesh", Severity::Failed));
  EXPECT_EQ(r.solidsWithHoles, 1);
  EXPECT_FALSE(r.mesh.tets.empty());
  EXPECT_NEAR(r.solids[0].volume, m.volume, kHoleVolumeTolerance * m.volume);
  EXPECT_FALSE(r.mesh.patchFaces.empty());
  EXPECT_EQ(joined(r.mesh.validate()), "");  // the patch faces close the holes
}

TEST(RayParity, InsideOutsideAndOnTheSurfaceOfACube) {
  std::vector<Vec3> p;
  for (int k = 0; k < 8; ++k) p.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  // the 12 triangles of the unit cube (any orientation: parity does not need it)
  const std::vector<std::array<int, 3>> t = {{0, 1, 3}, {0, 3, 2}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                             {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 3, 7}, {1, 7, 5}};
  const RayParity parity(p, t);
  EXPECT_EQ(parity.inside(Vec3(0.3, 0.4, 0.5)), std::optional<bool>(true));
  EXPECT_EQ(parity.inside(Vec3(0.999, 0.001, 0.5)), std::optional<bool>(true));
  EXPECT_EQ(parity.inside(Vec3(1.2, 0.5, 0.5)), std::optional<bool>(false));  // beside it, in no box
  EXPECT_EQ(parity.inside(Vec3(5, 5, 5)), std::optional<bool>(false));        // beyond its box
  EXPECT_EQ(parity.inside(Vec3(0.5, 0.5, 1.0)), std::nullopt);                // on its top: every ray degenerate
  // a cube with a cubic void: inside the void is outside
  std::vector<Vec3> q = p;
  for (int k = 0; k < 8; ++k) q.emplace_back(0.25 + 0.5 * (k & 1), 0.25 + 0.5 * ((k >> 1) & 1), 0.25 + 0.5 * ((k >> 2) & 1));
  std::vector<std::array<int, 3>> u = t;
  for (const auto& tri : t) u.push_back({tri[0] + 8, tri[1] + 8, tri[2] + 8});
  const RayParity hollow(q, u);
  EXPECT_EQ(hollow.inside(Vec3(0.5, 0.52, 0.48)), std::optional<bool>(false));
  EXPECT_EQ(hollow.inside(Vec3(0.1, 0.5, 0.5)), std::optional<bool>(true));
}
