// Tests of undoRefinementOfFailed (mesher/pipeline/UndoRefinement.h): a solid that failed on
// the finer surface loses its proximity sources, the user's and the other solids' stay.
#include <gtest/gtest.h>

#include "mesher/pipeline/UndoRefinement.h"

using namespace aniso;

namespace {

SizingSource sourceOn(std::vector<int> faces, double size) {
  SizingSource s;
  s.kind = SizingSource::Kind::Box;
  s.b = Vec3::Ones();
  s.metric = Metric3d::isotropic(size);
  s.faces = std::move(faces);
  return s;
}

/// Solid 0 on faces 0..2, solid 1 on faces 2..4 (face 2 shared: a label on a shield).
Model twoSolids() {
  Model model;
  model.faces.resize(5);
  model.shells.push_back({{{0, false}, {1, false}, {2, false}}, true});
  model.shells.push_back({{{2, true}, {3, false}, {4, false}}, true});
  model.solids.push_back({"shield", 0, {}, {}, 0});
  model.solids.push_back({"label", 1, {}, {}, 0});
  return model;
}

}  // namespace

TEST(UndoRefinement, TheFailedSolidsSourcesGoTheOthersStay) {
  const Model model = twoSolids();
  UserSizing sizing;
  sizing.sources = {sourceOn({}, 5.0),          // the user's (every face)
                    sourceOn({2, 3, 4}, 0.1),   // the user's too, on the label's faces: kept
                    sourceOn({0, 1, 2}, 0.5),   // the shield's proximity source
                    sourceOn({2, 3, 4}, 0.01),  // the label's
                    sourceOn({0, 1, 2, 3, 4}, 0.2)};  // a face of both: not the label's alone
  std::vector<SolidOutcome> solids(2);
  solids[1].status = SolidOutcome::Status::Failed;
  ProximityOutcome px;
  px.refined = {{0, 0.5}, {3, 0.01}, {2, 0.2}};
  px.facesRefined = 3;
  EXPECT_EQ(undoRefinementOfFailed(model, 2, solids, sizing, px), 1u);
  ASSERT_EQ(sizing.sources.size(), 4u);
  EXPECT_EQ(sizing.sources[1].metric.axes().lengths.minCoeff(), 0.1);
  EXPECT_EQ(sizing.sources[2].faces, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(sizing.sources[3].faces, (std::vector<int>{0, 1, 2, 3, 4}));
  // the label's faces leave the refined list, the shield's stays
  EXPECT_EQ(px.refined, (std::vector<std::pair<int, double>>{{0, 0.5}}));
  EXPECT_EQ(px.facesRefined, 1u);
}

TEST(UndoRefinement, NothingFailedNothingUndone) {
  const Model model = twoSolids();
  UserSizing sizing;
  sizing.sources = {sourceOn({0, 1, 2}, 0.5), sourceOn({2, 3, 4}, 0.01)};
  std::vector<SolidOutcome> solids(2);
  ProximityOutcome px;
  EXPECT_EQ(undoRefinementOfFailed(model, 0, solids, sizing, px), 0u);
  EXPECT_EQ(sizing.sources.size(), 2u);
}
