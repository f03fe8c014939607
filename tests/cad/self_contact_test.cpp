// A solid two of whose faces touch along a line through both, with no edge there
// (cad/PrepareSelfContacts.cpp): KiCad's battery holders, whose cradles are cylinders
// tangent to one another, pinch the wall between them to nothing. Unimprinted, the two
// faces' meshes pass each other a tolerance apart and the tetrahedra there are slivers
// (0.02–0.07°).
#include <gtest/gtest.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepTools.hxx>
#include <TopoDS.hxx>
#include <gp_Circ.hxx>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "cad/CadModel.h"
#include "mesher/pipeline/Pipeline.h"
#include "mesher/volume/ThinBoundary.h"
#include "tests/cad/mesh_volume.h"

namespace aniso::cad {
namespace {

/// A 10 × 8 block, 6 long along x, with two bores of radius 2 along x whose axes are 4
/// apart (at y = 3 and y = 7, z = 4): the bores touch along the line y = 5, z = 4. Written
/// as a BREP file.
std::string blockWithTangentBores() {
  BRepBuilderAPI_MakePolygon outer;
  for (const auto& [y, z] : std::vector<std::pair<double, double>>{{0, 0}, {10, 0}, {10, 8}, {0, 8}})
    outer.Add(gp_Pnt(0, y, z));
  outer.Close();
  BRepBuilderAPI_MakeFace face(outer.Wire(), true);
  for (const double y : {3.0, 7.0}) {
    // a hole: the circle walked clockwise seen from +x (the face's normal)
    const gp_Circ c(gp_Ax2(gp_Pnt(0, y, 4), gp_Dir(-1, 0, 0)), 2);
    face.Add(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(c).Edge()).Wire());
  }
  const TopoDS_Shape s = BRepPrimAPI_MakePrism(face.Face(), gp_Vec(6, 0, 0)).Shape();
  const auto path = std::filesystem::temp_directory_path() / "anisomesh_tangent_bores.brep";
  BRepTools::Write(s, path.string().c_str());
  return path.string();
}

TEST(SelfContact, TheLineWhereTwoBoresTouchBecomesAnEdgeOfBoth) {
  const std::string path = blockWithTangentBores();
  CadModel cad = CadModel::read(path);
  const PrepareReport r = cad.prepare({});
  std::filesystem::remove(path);
  const double volume = 6 * (80 - 2 * M_PI * 4);
  bool imprinted = false;
  for (const std::string& w : r.warnings) imprinted = imprinted || w.find("touch themselves along a line") != std::string::npos;
  EXPECT_TRUE(imprinted);
  ASSERT_EQ(cad.summary().solids, 1);
  EXPECT_NEAR(cad.summary().volume, volume, 1e-6 * volume);

  const Model model = cad.topology();
  // the contact line: one edge between four faces (each bore split in two along it)
  std::vector<int> uses(model.edges.size(), 0);
  for (const ModelFace& f : model.faces)
    for (const Loop& l : f.loops)
      for (const EdgeUse& u : l.uses) ++uses[static_cast<std::size_t>(u.edge)];
  ASSERT_EQ(std::count(uses.begin(), uses.end(), 4), 1);
  const ModelEdge& contact = model.edges[static_cast<std::size_t>(std::find(uses.begin(), uses.end(), 4) - uses.begin())];
  EXPECT_EQ(contact.faces.size(), 4u);

  MeshRequest request;
  request.options.dim = 3;
  const MeshResult m = meshModel(model, request);
  ASSERT_TRUE(m.meshed());
  // the cusps either side of the contact are no thin wall (ThinBoundary.h): without that
  // rule 186 of their triangles were reported thin
  EXPECT_EQ(m.proximity.thinTrianglesLeft, 0u);
  EXPECT_NEAR(meshVolume(m.volume.mesh), volume, 0.01 * volume);
}

// A thin-wall source (ThinBoundary.h) whose box would cover the contact line leaves it out,
// with kCuspClearance times its size around it: finer triangles at a cusp make its tets
// flatter (the battery holders at the defaults, 1.09-1.58 deg with the line inside a box).
TEST(SelfContact, ThinSourcesStayClearOfTheContactLine) {
  const std::string path = blockWithTangentBores();
  CadModel cad = CadModel::read(path);
  cad.prepare({});
  std::filesystem::remove(path);
  const Model model = cad.topology();
  const double thickness = 0.05;
  std::vector<ThinSpot> spots;
  for (const Vec3& c : {Vec3(0, 0, 0), Vec3(6, 10, 8), Vec3(3, 1, 1)}) spots.push_back({0, c, 1.0, thickness, 0});
  std::vector<std::pair<int, double>> faces;
  const std::vector<SizingSource> sources = thinSources(spots, 1e-3, &faces, &model);
  ASSERT_GT(sources.size(), 1u);  // the face's box, less the line's
  ASSERT_EQ(faces.size(), sources.size());
  const auto covered = [&](const Vec3& x) {
    return std::any_of(sources.begin(), sources.end(), [&](const SizingSource& s) { return s.contains(x); });
  };
  const double clear = kCuspClearance * thickness;
  for (const double x : {0.0, 3.0, 6.0}) {
    EXPECT_FALSE(covered(Vec3(x, 5, 4))) << x;  // on the line
    EXPECT_FALSE(covered(Vec3(x, 5 + 0.9 * clear, 4 - 0.9 * clear))) << x;
  }
  EXPECT_TRUE(covered(Vec3(3, 1, 1)));
  EXPECT_TRUE(covered(Vec3(3, 5 + 1.1 * clear, 4)));
  EXPECT_TRUE(covered(Vec3(3, 5, 4 + 1.1 * clear)));
}

}  // namespace
}  // namespace aniso::cad
