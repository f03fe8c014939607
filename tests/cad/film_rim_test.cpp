// Film rims and steps (mesher/model/EdgeNormals.h, filmRims): a face between two faces
// that face opposite ways across it is the rim of a sheet; a riser between two faces that
// face the same way is a step of the surface.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <filesystem>
#include <string>

#include "cad/CadModel.h"
#include "mesher/model/EdgeNormals.h"
#include "mesher/pipeline/Pipeline.h"

namespace aniso::cad {
namespace {

/// `shape` written as a BREP file, read and prepared.
Model prepared(const TopoDS_Shape& shape, const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / ("anisomesh_" + name + ".brep");
  BRepTools::Write(shape, path.string().c_str());
  CadModel cad = CadModel::read(path.string());
  cad.prepare({});
  std::filesystem::remove(path);
  return cad.topology();
}

/// A film 2 x 2 x 0.001 on a block 4 x 4 x 1, two solids.
TopoDS_Shape filmOnBlock() {
  TopoDS_Compound both;
  BRep_Builder builder;
  builder.MakeCompound(both);
  builder.Add(both, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(4, 4, 1)).Shape());
  builder.Add(both, BRepPrimAPI_MakeBox(gp_Pnt(1, 1, 1), gp_Pnt(3, 3, 1.001)).Shape());
  return both;
}

/// The faces of `shape` (written as a BREP file, read and prepared) that are film rims, and
/// how many faces there are.
std::pair<int, int> filmRims(const TopoDS_Shape& shape, const std::string& name) {
  const Model model = prepared(shape, name);
  const std::vector<std::uint8_t> rim = filmRims(model);
  const int rims = static_cast<int>(std::count(rim.begin(), rim.end(), 1));
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

TEST(FilmRim, AFilmLyingOnAPartHasRimsToo) {
  // the film's bottom is the block's top face, which faces up (out of the block); seen from
  // the film it faces down
  const auto [rims, faces] = filmRims(filmOnBlock(), "film_on_block");
  EXPECT_GE(faces, 12);
  EXPECT_EQ(rims, 4);
}

TEST(FilmRim, TheSurfaceRepairKeepsAFilmsRim) {
  // the rim is 1 um wide, below the repair's local tolerance (SurfaceSlivers.h) beside the
  // film's triangles: merged away, the film's top would slope down to its bottom around
  // its edge (volume lost, flatter tets)
  const Model model = prepared(filmOnBlock(), "film_repair");
  MeshRequest request;
  request.options.dim = 2;
  request.options.sizing.anisotropy = 1;  // as the program's default
  const MeshResult r = meshModel(model, request);
  ASSERT_TRUE(r.meshed());
  // the film's top: the face whose triangles lie highest; every node of it at z = 1.001
  const SurfaceMesh& m = r.surface.mesh;
  std::vector<double> zSum(model.faces.size(), 0);
  std::vector<int> count(model.faces.size(), 0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (const int v : m.triangles[t]) {
      zSum[static_cast<std::size_t>(m.triangleFace[t])] += m.nodes[static_cast<std::size_t>(v)].z();
      ++count[static_cast<std::size_t>(m.triangleFace[t])];
    }
  std::size_t top = 0;
  for (std::size_t f = 0; f < zSum.size(); ++f)
    if (count[f] > 0 && zSum[f] / count[f] > zSum[top] / std::max(count[top], 1)) top = f;
  int lowered = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (static_cast<std::size_t>(m.triangleFace[t]) == top)
      for (const int v : m.triangles[t]) lowered += m.nodes[static_cast<std::size_t>(v)].z() < 1.001 - 1e-9 ? 1 : 0;
  EXPECT_EQ(lowered, 0);
  EXPECT_EQ(r.surfaceRepair.nodesMerged, 0);
}

}  // namespace
}  // namespace aniso::cad
