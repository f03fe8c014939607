// The surface repair stage is the same for both dimensions (issue 16): on a model whose 3D
// run refines no face (no proximity round, no coarse-solid retry, no boundary split),
// meshModel at dim 2 with anisotropy 1 and at dim 3 give the same surface — the same nodes
// and triangles — and it satisfies the geometric postcondition (SurfaceGeometry.h).
// part.step at --hmax-rel 0.1 has caps the repair flips, so the stage is exercised.
#include <gtest/gtest.h>

#include <string>

#include "cad/CadModel.h"
#include "mesher/pipeline/Pipeline.h"

namespace aniso {
namespace {

Model readModel(const std::string& path) {
  cad::CadModel cad = cad::CadModel::read(path);
  cad.prepare({});
  return cad.topology();
}

MeshResult mesh(const Model& model, int dim) {
  MeshRequest request;
  request.options.dim = dim;
  request.options.maxElements = 1e8;
  request.options.sizing.hmaxRel = 0.1;
  request.options.sizing.anisotropy = 1;
  return meshModel(model, request);
}

TEST(SurfaceRepairStage, SurfaceAndVolumeRunsShareTheRepairedSurface) {
  const Model model = readModel(std::string(ANISOMESH_SHARED_DIR) + "/models/part.step");
  const MeshResult s = mesh(model, 2), v = mesh(model, 3);
  ASSERT_TRUE(s.meshed());
  ASSERT_TRUE(v.meshed());
  // the case's premise: the 3D run changed no face after the surface stage
  ASSERT_EQ(v.proximity.rounds, 0);
  ASSERT_FALSE(v.coarse.refinedKept);
  ASSERT_EQ(v.volume.boundarySplits, 0);
  EXPECT_GT(s.surfaceRepair.capsFlipped, 0);  // the stage did something in 2D too
  EXPECT_EQ(s.surfaceRepair.capsFlipped, v.surfaceRepair.capsFlipped);

  const SurfaceMesh& a = s.surface.mesh;
  const SurfaceMesh& b = v.volume.mesh.surface;  // its surface nodes first, then the solids'
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.triangleFace, b.triangleFace);
  ASSERT_LE(a.nodes.size(), b.nodes.size());
  for (std::size_t n = 0; n < a.nodes.size(); ++n) ASSERT_EQ(a.nodes[n], b.nodes[n]) << "node " << n;

  const SurfaceGeometryCheck c = checkSurfaceGeometry(model, a);
  EXPECT_TRUE(c.ok()) << (c.messages().empty() ? std::string() : c.messages().front());
  EXPECT_TRUE(s.surfaceCheck.ok());

  // the validator has teeth on this model: a triangle taken out opens its solid
  SurfaceMesh open = a;
  open.triangles.pop_back();
  open.triangleFace.pop_back();
  EXPECT_GT(checkSurfaceGeometry(model, open).openEdges, 0);
}

}  // namespace
}  // namespace aniso
