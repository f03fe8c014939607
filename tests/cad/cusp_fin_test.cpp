// A fin standing on a contact edge, closing a cusp there (cad/CuspFins.cpp): KiCad's
// battery holders, once the line where two cradles touch is imprinted, keep a fin 0.3 mm
// tall and 0–18 µm thick above it whose tetrahedra cannot have angles above 1–3°.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>

#include <cmath>
#include <vector>

#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {
namespace {

/// A 4 × 4 × 1 plate between two 1 × 4 × 2 walls (x from −1 to 0 and from 4 to 5), and a
/// fin along x from 0 to 4 whose edge (y = 2, z = 1) stands on the plate: `height` tall,
/// `top` wide at its top, running into both walls. Fused: the fin's edge splits the plate's top
/// face in two.
TopoDS_Shape plateWithFin(double top, double height = 0.1) {
  BRepBuilderAPI_MakePolygon p;
  p.Add(gp_Pnt(0, 2, 1));
  p.Add(gp_Pnt(0, 2 - top / 2, 1 + height));
  p.Add(gp_Pnt(0, 2 + top / 2, 1 + height));
  p.Close();
  const TopoDS_Shape fin = BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(p.Wire(), true).Face(), gp_Vec(4, 0, 0)).Shape();
  TopTools_ListOfShape args, tools;
  args.Append(BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(4, 4, 1)).Shape());
  tools.Append(BRepPrimAPI_MakeBox(gp_Pnt(4, 0, 0), gp_Pnt(5, 4, 2)).Shape());
  tools.Append(BRepPrimAPI_MakeBox(gp_Pnt(-1, 0, 0), gp_Pnt(0, 4, 2)).Shape());
  tools.Append(fin);
  BRepAlgoAPI_Fuse fuse;
  fuse.SetArguments(args);
  fuse.SetTools(tools);
  fuse.Build();
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(fuse.Shape(), TopAbs_SOLID, solids);
  return solids.Extent() == 1 ? solids(1) : TopoDS_Shape();
}

/// The edges of `s` between four faces.
std::vector<TopoDS_Shape> fourFaceEdges(const TopoDS_Shape& s) {
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(s, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  std::vector<TopoDS_Shape> out;
  for (int i = 1; i <= edgeFaces.Extent(); ++i) {
    TopTools_IndexedMapOfShape distinct;
    for (const TopoDS_Shape& f : edgeFaces(i)) distinct.Add(f);
    if (distinct.Extent() == 4) out.push_back(edgeFaces.FindKey(i));
  }
  return out;
}

double diagonalOf(const TopoDS_Shape& s) {
  Bnd_Box box;
  BRepBndLib::Add(s, box);
  return std::sqrt(box.SquareExtent());
}

TEST(CuspFin, AThinFinOnACuspIsTakenOffAndTheSolidStaysClosed) {
  const TopoDS_Shape s = plateWithFin(0.004);  // sides 2.3° apart at the edge
  ASSERT_FALSE(s.IsNull());
  const std::vector<TopoDS_Shape> contact = fourFaceEdges(s);
  ASSERT_EQ(contact.size(), 1u);
  const std::optional<FinRemoval> r = withoutCuspFins(s, contact, diagonalOf(s));
  ASSERT_TRUE(r.has_value());
  const double fin = 4 * 0.1 * 0.004 / 2;
  EXPECT_NEAR(r->volume, fin, 1e-3 * fin);
  EXPECT_NEAR(std::abs(solidVolume(r->solid)), 16 + 8 + 8, 1e-6);
  EXPECT_TRUE(BRepCheck_Analyzer(r->solid).IsValid());
  EXPECT_TRUE(fourFaceEdges(r->solid).empty());
}

TEST(CuspFin, AFinThatOpensOrIsThickStays) {
  // sides 11° apart, and as thin as the cusp fin above (2V/A 0.0018): only the angle keeps it
  const TopoDS_Shape wedge = plateWithFin(0.004, 0.02);
  ASSERT_FALSE(wedge.IsNull());
  EXPECT_FALSE(withoutCuspFins(wedge, fourFaceEdges(wedge), diagonalOf(wedge)).has_value());
  // a cusp, but the model so small that the fin is thick for it
  const TopoDS_Shape s = plateWithFin(0.004);
  EXPECT_FALSE(withoutCuspFins(s, fourFaceEdges(s), 0.1).has_value());
}

}  // namespace
}  // namespace aniso::cad::detail
