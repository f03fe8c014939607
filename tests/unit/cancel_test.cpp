// CancelToken (mesher/core/Cancel.h): the deadline, the request, the message naming the
// phase, and that a parallelFor stops all its workers.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

#include "mesher/core/Cancel.h"
#include "mesher/core/ParallelFor.h"
#include "mesher/pipeline/SurfaceMesher.h"
#include "mesher/volume/VolumeMesher.h"
#include "contour_test_models.h"
#include "volume_test_models.h"

namespace aniso {

TEST(Cancel, NoDeadlineNeverStopsUntilRequested) {
  const CancelToken token;
  EXPECT_FALSE(token.stopped());
  EXPECT_NO_THROW(token.check("x"));
  token.request();
  EXPECT_TRUE(token.stopped());
  EXPECT_THROW(token.check("x"), Cancelled);
}

TEST(Cancel, DeadlineNamesTheLimitAndThePhase) {
  const CancelToken token(0.01);
  EXPECT_NO_THROW(token.check("early"));
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  try {
    token.check("volume refinement");
    FAIL() << "no Cancelled after the deadline";
  } catch (const Cancelled& e) {
    EXPECT_EQ(e.phase(), "volume refinement");
    EXPECT_STREQ(e.what(), "stopped after the time limit of 0.01 s during volume refinement");
  }
}

TEST(Cancel, PollChecksEveryPeriodOnly) {
  const CancelToken token;
  token.request();
  CancelPoll poll(&token, "loop", 4);
  EXPECT_NO_THROW(poll.tick());
  EXPECT_NO_THROW(poll.tick());
  EXPECT_NO_THROW(poll.tick());
  EXPECT_THROW(poll.tick(), Cancelled);
  CancelPoll none(nullptr, "loop", 1);
  EXPECT_NO_THROW(none.tick());
}

TEST(Cancel, OneWorkerStopsTheOthers) {
  // Worker 0 requests the stop; the others spin on check() and must all leave.
  const CancelToken token;
  EXPECT_THROW(parallelFor(
                   4, 4,
                   [&](int i) {
                     if (i == 0) {
                       token.request();
                       token.check("phase");
                     }
                     for (long k = 0; k < 2'000'000'000L; ++k) {
                       token.check("phase");
                     }
                   },
                   "test"),
               Cancelled);
  EXPECT_TRUE(token.stopped());
}

// The meshers stop at their first check and name the phase; no partial result escapes.
namespace {

/// Runs mesh(options) with a token already stopped: it must throw Cancelled naming phase.
template <class Input, class Mesh>
void expectStoppedIn(Input in, Mesh mesh, const std::string& phase) {
  auto token = std::make_shared<CancelToken>();
  token->request();
  in.options.cancel = token;
  try {
    mesh(in);
    ADD_FAILURE() << "no Cancelled";
  } catch (const Cancelled& e) {
    EXPECT_EQ(e.phase(), phase);
  }
}

}  // namespace

TEST(Cancel, SurfaceMesherStopsAndNamesThePhase) {
  const Model m = test::sphere();
  SurfaceMesherInput in;
  in.model = &m;
  in.options.threads = 2;
  in.options.sizing.hmaxRel = 0.05;
  const SurfaceMeshResult whole = meshSurfaces(in);  // the same options with no token: meshes
  ASSERT_TRUE(whole.ok());
  expectStoppedIn(in, meshSurfaces, "control spaces");
}

TEST(Cancel, VolumeMesherStopsAndNamesThePhase) {
  const voltest::SolidModel m = voltest::gridCube(3, false);
  VolumeMesherInput in;
  in.model = &m.model;
  in.surface = &m.surface;
  in.options.threads = 2;
  in.refine = in.improve = in.quality = false;
  ASSERT_TRUE(meshVolumes(in).ok());  // no token: meshes
  expectStoppedIn(in, meshVolumes, "volume meshing");
}

}  // namespace aniso
