// meshFace inside the surface pipeline on curved analytic faces (M = M_s M_p with the
// surface's parameterization tensor): edges discretized and face boundaries built by the
// contour discretization (alg. 4.1), faces meshed, assembled into a SurfaceMesh. A sphere
// (seam and two poles) and a cylinder (seam) must give closed, consistently oriented,
// manifold surfaces whose edge lengths follow the sizing on the surface.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <memory>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/metric/QualityStats.h"
#include "mesher/surface/ContourDiscretization.h"
#include "mesher/surface/FaceMesher.h"
#include "mesher/surface/face/SurfaceOrientation.h"
#include "mesher/surface/face/ValidateFaceMesh.h"
#include "tests/unit/contour_test_models.h"

using namespace aniso;

namespace {

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

struct Meshed {
  SurfaceMesh mesh;
  std::vector<FaceMeshResult> faces;
};

/// Meshes every face with the fold guard (FaceMesherOptions::surface) and checks each face
/// mesh with the (u, v) validator and the fold validator.
Meshed meshModel(const Model& m, double h, double gMin) {
  std::vector<std::unique_ptr<CSAnalytic2d>> spaces;
  std::vector<const ControlSpace2d*> ptrs;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    spaces.push_back(test::space(m, static_cast<int>(f), test::isotropic(h), gMin));
    ptrs.push_back(spaces.back().get());
  }
  Meshed out;
  const std::vector<EdgeDiscretization> edges = discretizeEdges(m, ptrs, {}, out.mesh);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const FaceBoundary b = faceBoundary(m, static_cast<int>(f), edges, out.mesh);
    FaceMesherOptions options;
    options.surface = m.faces[f].surface.get();
    FaceMeshResult r = meshFace(b, *ptrs[f], options);
    EXPECT_TRUE(r.ok()) << joined(r.problems);
    const auto problems = face::validateFaceMesh(r.mesh, b);
    EXPECT_TRUE(problems.empty()) << joined(problems);
    EXPECT_TRUE(face::foldedTriangles(r.mesh, *m.faces[f].surface).empty()) << "face " << f;
    EXPECT_EQ(r.stats.foldsLeft, 0) << "face " << f;
    if (r.ok()) addFaceMesh(m, static_cast<int>(f), r.mesh, out.mesh);
    out.faces.push_back(std::move(r));
  }
  return out;
}

/// Mean and spread of the 3D edge lengths over the requested size.
void expectEdgeLengths(const SurfaceMesh& mesh, double h) {
  std::vector<std::pair<int, int>> edges;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) edges.emplace_back(std::minmax(t[i], t[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  QualityStats s;
  std::size_t inRange = 0;
  for (const auto& [a, b] : edges) {
    const double l = (mesh.nodes[a] - mesh.nodes[b]).norm() / h;
    s.add(l);
    inRange += l > 0.5 && l < 1.6;
  }
  EXPECT_NEAR(s.mean(), 1.0, 0.12);
  EXPECT_GT(static_cast<double>(inRange), 0.95 * static_cast<double>(s.count()));
}

void expectClosed(const SurfaceMesh& mesh) {
  EXPECT_TRUE(mesh.validate().empty()) << joined(mesh.validate());
  const SurfaceMesh::EdgeCounts c = mesh.edgeCounts();
  EXPECT_EQ(c.open, 0);
  EXPECT_EQ(c.nonManifold, 0);
  EXPECT_EQ(c.misoriented, 0);
}

TEST(FaceMesherSurface, SphereWithSeamAndPolesIsClosed) {
  const double h = 0.1;
  const Meshed r = meshModel(test::sphere(1.0), h, 1e-4);
  ASSERT_FALSE(r.mesh.triangles.empty());
  expectClosed(r.mesh);
  expectEdgeLengths(r.mesh, h);
  // Euler characteristic of the sphere: V − E + F = 2 (all nodes used).
  std::vector<std::pair<int, int>> edges;
  for (const auto& t : r.mesh.triangles)
    for (int i = 0; i < 3; ++i) edges.emplace_back(std::minmax(t[i], t[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const long long chi = static_cast<long long>(r.mesh.nodes.size()) - static_cast<long long>(edges.size()) +
                        static_cast<long long>(r.mesh.triangles.size());
  EXPECT_EQ(chi, 2);
  // Triangles approximate the sphere: area ≈ 4π.
  double area = 0;
  for (const auto& t : r.mesh.triangles)
    area += 0.5 * (r.mesh.nodes[t[1]] - r.mesh.nodes[t[0]]).cross(r.mesh.nodes[t[2]] - r.mesh.nodes[t[0]]).norm();
  EXPECT_NEAR(area, 4 * test::kPi, 0.02 * 4 * test::kPi);
}

TEST(FaceMesherSurface, SingularParameterizationAtThePoles) {
  // gMin = 0: M_p (and M) is singular on the pole rows; the mesher must still give a valid,
  // closed mesh (insertions with an unusable metric are cancelled or done with I).
  const Meshed r = meshModel(test::sphere(1.0), 0.2, 0);
  ASSERT_FALSE(r.mesh.triangles.empty());
  expectClosed(r.mesh);
}

TEST(FaceMesherSurface, NoFoldsAtThePolesOverSizes) {
  // Coarse to fine sizes around the poles of a sphere: every triangle upright on the
  // surface (checked in meshModel), the surface closed.
  for (const double h : {0.45, 0.3, 0.17, 0.09, 0.05}) {
    const Meshed r = meshModel(test::sphere(1.0), h, 1e-4);
    ASSERT_FALSE(r.mesh.triangles.empty()) << h;
    expectClosed(r.mesh);
  }
}

TEST(FaceMesherSurface, ControlSpaceFailureIsAProblemNotAnException) {
  const Model m = test::unitSquare();
  const auto good = test::space(m, 0, test::isotropic(0.1));
  std::vector<const ControlSpace2d*> ptrs = {good.get()};
  SurfaceMesh mesh;
  const auto edges = discretizeEdges(m, ptrs, {}, mesh);
  const FaceBoundary b = faceBoundary(m, 0, edges, mesh);
  const CSAnalytic2d failing(m.faces[0].uvBounds, [](const Vec2& uv) {
    if (uv.x() > 0.4 && uv.x() < 0.6 && uv.y() > 0.4 && uv.y() < 0.6) throw MeshingError("no metric here");
    return Metric2d::isotropic(0.1);
  });
  FaceMeshResult r;
  EXPECT_NO_THROW(r = meshFace(b, failing));
  EXPECT_FALSE(r.ok());
  EXPECT_TRUE(r.mesh.triangles.empty());
  ASSERT_FALSE(r.problems.empty());
  EXPECT_NE(r.problems.front().find("no metric here"), std::string::npos) << r.problems.front();
}

TEST(FaceMesherSurface, CylinderSeamIsConforming) {
  const double h = 0.15;
  const Meshed r = meshModel(test::cylinder(1.0, 2.0), h, 0);
  ASSERT_FALSE(r.mesh.triangles.empty());
  EXPECT_TRUE(r.mesh.validate().empty()) << joined(r.mesh.validate());
  const SurfaceMesh::EdgeCounts c = r.mesh.edgeCounts();
  EXPECT_EQ(c.nonManifold, 0);
  EXPECT_EQ(c.misoriented, 0);
  // Only the two circles are open (the lateral face alone): 2 × the circle's segments.
  std::size_t circleNodes = 0;
  for (const auto& on : r.mesh.nodeOn) circleNodes += on.kind != NodeOn::Kind::Face;
  EXPECT_GT(c.open, 0);
  EXPECT_LE(static_cast<std::size_t>(c.open), circleNodes);
  expectEdgeLengths(r.mesh, h);
}

}  // namespace
