// Tests of the smoothing schedule (mesher/volume/improve/SmoothingSchedule.h) and of the
// improvement's threads: blocks of one class never share a tet, and the mesh does not depend
// on the number of threads.
#include <gtest/gtest.h>

#include <cstring>
#include <numeric>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/volume/VolumeImprovement.h"
#include "mesher/volume/VolumeRefinement.h"
#include "mesher/volume/improve/SmoothingSchedule.h"
#include "mesher/volume/improve/VertexTets.h"
#include "volume_refine_fixture.h"

using namespace aniso;
using namespace aniso::testing;

namespace {

CSAnalytic3d graded() {
  return CSAnalytic3d(unitBox(), [](const Vec3& x) { return Metric3d::isotropic(0.04 + 0.1 * x.z()); });
}

TEST(SmoothingSchedule, BlocksOfAClassShareNoTet) {
  std::set<Triple> boundary;
  SolidTetMesh s = cubeSolid(8, boundary);
  const CSAnalytic3d cs = graded();
  refineVolume(s, cs);
  const improve3d::VertexTets inc(s.mesh);
  std::vector<std::uint32_t> order(s.mesh.numVertices());
  std::iota(order.begin(), order.end(), 0u);
  for (const std::size_t block : {std::size_t{1}, std::size_t{7}, std::size_t{64}}) {
    const improve3d::SmoothingSchedule sch = improve3d::smoothingSchedule(s.mesh, inc, order, block);
    EXPECT_TRUE(improve3d::scheduleIndependent(s.mesh, sch)) << "block " << block;
    EXPECT_EQ(sch.vertices, order);
    EXPECT_GT(sch.classes(), 1u);
    EXPECT_LT(sch.classes(), 64u) << "greedy colouring of a tet mesh needs a few dozen classes at most";
  }
  // the validator has teeth: two neighbours put into one class as different blocks
  improve3d::SmoothingSchedule bad;
  const std::uint32_t* tv = s.mesh.tetVertices(del3d::TetId(0));
  ASSERT_TRUE(s.mesh.isAlive(del3d::TetId(0)));
  bad.vertices = {tv[0], tv[1]};
  bad.blockStart = {0, 1, 2};
  bad.blocks = {0, 1};
  bad.classStart = {0, 2};
  EXPECT_FALSE(improve3d::scheduleIndependent(s.mesh, bad));
  bad.classStart = {0, 1, 2};
  EXPECT_TRUE(improve3d::scheduleIndependent(s.mesh, bad));
}

TEST(VolumeImprove, SameMeshForAnyNumberOfThreads) {
  std::set<Triple> boundary;
  const CSAnalytic3d cs = graded();
  SolidTetMesh base = cubeSolid(10, boundary);
  refineVolume(base, cs);
  std::vector<SolidTetMesh> out;
  std::vector<std::size_t> moved;
  for (const int threads : {1, 2, 3}) {
    SolidTetMesh s = base;
    VolumeImproveOptions o;
    o.threads = threads;
    moved.push_back(improveVolume(s, cs, o).moved);
    ASSERT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
    out.push_back(std::move(s));
  }
  EXPECT_GT(moved[0], 0u);
  for (std::size_t k = 1; k < out.size(); ++k) {
    EXPECT_EQ(moved[k], moved[0]);
    ASSERT_EQ(out[k].mesh.numVertices(), out[0].mesh.numVertices());
    ASSERT_EQ(out[k].mesh.tetSlots(), out[0].mesh.tetSlots());
    for (std::uint32_t v = 0; v < out[0].mesh.numVertices(); ++v)
      ASSERT_EQ(std::memcmp(out[k].mesh.coords(del3d::VertexId(v)), out[0].mesh.coords(del3d::VertexId(v)),
                            3 * sizeof(double)),
                0)
          << "vertex " << v << " with " << k + 1 << " threads";
    for (std::uint32_t t = 0; t < out[0].mesh.tetSlots(); ++t) {
      ASSERT_EQ(out[k].mesh.isAlive(del3d::TetId(t)), out[0].mesh.isAlive(del3d::TetId(t)));
      if (out[0].mesh.isAlive(del3d::TetId(t))) {
        ASSERT_EQ(std::memcmp(out[k].mesh.tetVertices(del3d::TetId(t)), out[0].mesh.tetVertices(del3d::TetId(t)),
                              4 * sizeof(std::uint32_t)),
                  0)
            << "tet " << t;
      }
    }
  }
}

}  // namespace
