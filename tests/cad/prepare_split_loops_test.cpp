// splitLoopsOfClosedEdges (cad/detail/Prepare.h), through CadModel::prepare: a cylinder face
// whose one loop holds both rim circles and no seam is healed into a face with two loops
// and a seam, which the mesher can read.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "cad/CadModel.h"
#include "tests/cad/step_text.h"

namespace aniso::cad {
namespace {

// A cylinder of radius 2 and height 3; the face's single FACE_OUTER_BOUND lists the bottom
// and the top circle, each an edge from its own vertex back to it.
const std::string kRimsInOneLoop = test::stepWithContext(R"(#20=CARTESIAN_POINT('',(0.,0.,0.));
#21=DIRECTION('',(0.,0.,1.));
#22=DIRECTION('',(1.,0.,0.));
#23=AXIS2_PLACEMENT_3D('',#20,#21,#22);
#24=CYLINDRICAL_SURFACE('',#23,2.);
#30=CARTESIAN_POINT('',(2.,0.,0.));
#31=VERTEX_POINT('',#30);
#32=CIRCLE('',#23,2.);
#33=EDGE_CURVE('bottom rim',#31,#31,#32,.T.);
#40=CARTESIAN_POINT('',(0.,0.,3.));
#41=AXIS2_PLACEMENT_3D('',#40,#21,#22);
#42=CIRCLE('',#41,2.);
#43=CARTESIAN_POINT('',(2.,0.,3.));
#44=VERTEX_POINT('',#43);
#45=EDGE_CURVE('top rim',#44,#44,#42,.T.);
#50=ORIENTED_EDGE('',*,*,#33,.T.);
#51=ORIENTED_EDGE('',*,*,#45,.F.);
#52=EDGE_LOOP('',(#50,#51));
#53=FACE_OUTER_BOUND('',#52,.T.);
#54=ADVANCED_FACE('mantle',(#53),#24,.T.);
#60=OPEN_SHELL('',(#54));
#61=SHELL_BASED_SURFACE_MODEL('',(#60));
#62=MANIFOLD_SURFACE_SHAPE_REPRESENTATION('',(#61),#12);
#63=SHAPE_DEFINITION_REPRESENTATION(#7,#62);
)");

TEST(SplitLoops, RimCirclesInOneLoopBecomeTwoLoopsAndASeam) {
  const std::string path = test::writeTempStep("rims_in_one_loop.stp", kRimsInOneLoop);
  CadModel m = CadModel::read(path);
  EXPECT_NEAR(m.summary().area, 0.0, 1e-9);  // as read: the face has no extent
  const PrepareReport r = m.prepare({});
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("split into one loop per edge"), std::string::npos) << r.warnings[0];
  const ShapeSummary s = m.summary();
  EXPECT_EQ(s.faces, 1);
  EXPECT_EQ(s.edges, 3);  // two rims and the seam
  EXPECT_NEAR(s.area, 2 * std::numbers::pi * 2 * 3, 1e-6);
  const Model topo = m.topology();
  EXPECT_TRUE(topo.validate().empty());
  ASSERT_EQ(topo.faces.size(), 1u);
  EXPECT_EQ(topo.faces[0].loops.size(), 1u);  // one loop: bottom, seam, top, seam
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace aniso::cad
