// dropEmptySolids (cad/detail/Readers.h), through CadModel::read: a solid that holds no face
// (OCCT's sample Axis_of_bearing.brep has one among 18) is left out with a warning and counted
// as lost; the other solids keep their ids' names and the model meshes.
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cad/CadModel.h"

namespace aniso::cad {
namespace {

TEST(EmptySolid, IsLeftOutAndTheOthersKeepTheirNames) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 1, 1, 1).Shape());
  TopoDS_Solid empty;
  b.MakeSolid(empty);
  b.Add(c, empty);
  b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(3, 0, 0), 1, 2, 1).Shape());
  const std::string path = (std::filesystem::temp_directory_path() / "anisomesh_empty_solid.brep").string();
  ASSERT_TRUE(BRepTools::Write(c, path.c_str()));

  CadModel m = CadModel::read(path);
  EXPECT_EQ(m.solidsLost(), 1);
  EXPECT_EQ(m.summary().solids, 2);
  m.prepare(PrepareOptions{});
  const Model model = m.topology();
  ASSERT_EQ(model.solids.size(), 2u);
  EXPECT_EQ(model.solids[0].name, "SOLID1");
  EXPECT_EQ(model.solids[1].name, "SOLID3");  // its place in the file, not 2
  EXPECT_NEAR(m.summary().volume, 3.0, 1e-9);
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace aniso::cad
