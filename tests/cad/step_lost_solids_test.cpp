// lostSolids (cad/detail/Readers.h): the solid B-reps a STEP file declares against the solids
// a transfer gave; the readers rebuild a solid whose faces close and turn any other loss into
// a warning (a solid OCCT drops, or builds only as faces, must not vanish silently).
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cad/CadModel.h"
#include "cad/detail/Readers.h"
#include "mesher/core/Error.h"
#include "tests/cad/step_text.h"

namespace aniso::cad::detail {
namespace {

const std::string kModels = std::string(ANISOMESH_SOURCE_DIR) + "/models/";

int solidCount(const TopoDS_Shape& s) {
  TopTools_IndexedMapOfShape m;
  TopExp::MapShapes(s, TopAbs_SOLID, m);
  return m.Extent();
}

TEST(LostSolids, CountsTheSolidBrepsTheShapeLacks) {
  STEPControl_Reader reader;
  loadStepFile(reader, kModels + "bracket.step");
  ASSERT_GT(reader.TransferRoots(), 0);
  TopoDS_Shape read = reader.OneShape();
  EXPECT_EQ(lostSolids(reader, read), "");
  TopoDS_Shape nothing;
  TopoDS_Compound c;
  BRep_Builder().MakeCompound(c);
  nothing = c;
  EXPECT_EQ(lostSolids(reader, nothing),
            "1 of 1 solid(s) could not be transferred (their faces, if any were read, are meshed as surfaces: "
            "no tetrahedra inside)");
}

// A solid B-rep that came out of the transfer as its faces only (what OCCT gives for a
// MANIFOLD_SOLID_BREP over an OPEN_SHELL in a surface representation): the faces close, so
// the solid is rebuilt from them, outward, with the cube's volume.
TEST(LostSolids, RebuildsASolidWhoseFacesClose) {
  const std::string path = test::writeTempStep(
      "lost_solid_open_shell.stp", test::unitCubeStep("OPEN_SHELL", "MANIFOLD_SURFACE_SHAPE_REPRESENTATION"));
  STEPControl_Reader reader;
  loadStepFile(reader, path);
  ASSERT_GT(reader.TransferRoots(), 0);
  TopoDS_Compound faces;
  BRep_Builder b;
  b.MakeCompound(faces);
  for (TopExp_Explorer f(reader.OneShape(), TopAbs_FACE); f.More(); f.Next()) b.Add(faces, f.Current());
  TopoDS_Shape shape = faces;
  int notRebuilt = -1;
  const std::string message = lostSolids(reader, shape, &notRebuilt);
  EXPECT_NE(message.find("rebuilt as solid(s) from their faces"), std::string::npos) << message;
  EXPECT_EQ(message.find("could not be transferred"), std::string::npos) << message;
  EXPECT_EQ(notRebuilt, 0);
  ASSERT_EQ(solidCount(shape), 1);
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props);
  EXPECT_NEAR(props.Mass(), 1.0, 1e-9);

  const CadModel m = CadModel::read(path);  // the whole reader: a solid, nothing lost
  EXPECT_EQ(m.solidsLost(), 0);
  const ShapeSummary s = m.summary();
  EXPECT_EQ(s.solids, 1);
  EXPECT_NEAR(s.volume, 1.0, 1e-9);
  std::filesystem::remove(path);
}

// The same solid missing its top face: the faces do not close, nothing is rebuilt, and the
// model says so (CadModel::solidsLost, which the run turns into a degraded status).
TEST(LostSolids, KeepsTheFacesOfAnOpenShellThatDoesNotClose) {
  std::string text = test::unitCubeStep("OPEN_SHELL", "MANIFOLD_SURFACE_SHAPE_REPRESENTATION");
  const std::string all = "(#102,#112,#122,", noTop = "(#102,#122,";
  ASSERT_NE(text.find(all), std::string::npos);
  text.replace(text.find(all), all.size(), noTop);
  const std::string path = test::writeTempStep("lost_solid_open_box.stp", text);
  const CadModel m = CadModel::read(path);
  EXPECT_EQ(m.solidsLost(), 1);
  const ShapeSummary s = m.summary();
  EXPECT_EQ(s.solids, 0);
  EXPECT_EQ(s.faces, 5);
  std::filesystem::remove(path);
}

// A file whose faces no transferred shape holds (here a representation of only a placement):
// the empty model's message says the file had faces and how many.
TEST(LostSolids, AnEmptyModelCountsTheFacesOfTheFile) {
  std::string text = test::unitCubeStep("CLOSED_SHELL", "SHAPE_REPRESENTATION");
  const std::string items = "('',(#201),#12)";
  ASSERT_NE(text.find(items), std::string::npos);
  text.replace(text.find(items), items.size(), "('',(#101),#12)");
  const std::string path = test::writeTempStep("faces_not_used.stp", text);
  try {
    CadModel::read(path);
    ADD_FAILURE() << "an empty model was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("none of the file's 6 face(s) could be read"), std::string::npos) << e.what();
  }
  std::filesystem::remove(path);
}

// The control: the same cube over a CLOSED_SHELL is read as it is, with nothing to say.
TEST(LostSolids, LeavesAClosedShellSolidAlone) {
  const std::string path = test::writeTempStep("lost_solid_closed_shell.stp", test::unitCubeStep("CLOSED_SHELL"));
  STEPControl_Reader reader;
  loadStepFile(reader, path);
  ASSERT_GT(reader.TransferRoots(), 0);
  TopoDS_Shape shape = reader.OneShape();
  EXPECT_EQ(lostSolids(reader, shape), "");
  EXPECT_EQ(solidCount(shape), 1);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace aniso::cad::detail
