// Film rims and steps (mesher/model/EdgeNormals.h, isFilmRim): a face between two faces
// that face opposite ways across it is the rim of a sheet; a riser between two faces that
// face the same way is a step of the surface.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>

#include <filesystem>
#include <string>

#include "cad/CadModel.h"
#include "mesher/model/EdgeNormals.h"

namespace aniso::cad {
namespace {

/// The faces of `shape` (written as a BREP file, read and prepared) that are film rims, and
/// how many faces there are.
std::pair<int, int> filmRims(const TopoDS_Shape& shape, const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / ("anisomesh_" + name + ".brep");
  BRepTools::Write(shape, path.string().c_str());
  CadModel cad = CadModel::read(path.string());
  cad.prepare({});
  std::filesystem::remove(path);
  const Model model = cad.topology();
  int rims = 0;
  for (int f = 0; f < static_cast<int>(model.faces.size()); ++f) rims += isFilmRim(model, f) ? 1 : 0;
  return {rims, static_cast<int>(model.faces.size())};
}

TEST(FilmRim, TheSidesOfASheetAreRims) {
  // 4 x 3 x 0.001: the four sides lie between the top and the bottom
  const auto [rims, faces] = filmRims(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(4, 3, 0.001)).Shape(), "sheet");
  EXPECT_EQ(faces, 6);
  EXPECT_EQ(rims, 4);
}

TEST(FilmRim, AStepIsNoRimNorIsABlock) {
  // a block 4 x 4 x 1 with a pad 2 x 4 x 0.001 on its top: the pad's riser at x = 2 lies
  // between two faces facing up, its ends between the top and a side
  BRepAlgoAPI_Fuse fuse(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(4, 4, 1)).Shape(),
                        BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 1), gp_Pnt(2, 4, 1.001)).Shape());
  ASSERT_TRUE(fuse.IsDone());
  const auto [rims, faces] = filmRims(fuse.Shape(), "step");
  EXPECT_GE(faces, 8);
  EXPECT_EQ(rims, 0);
  EXPECT_EQ(filmRims(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(4, 3, 2)).Shape(), "block").first, 0);
}

}  // namespace
}  // namespace aniso::cad
