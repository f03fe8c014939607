// A solid that touches itself without crossing (cad/PrepareSelfIntersections.cpp): an edge
// of it lies on one of its faces, in no loop of that face. KiCad's common-mode toroids have
// eight such contacts (flat strips whose middle line is the edge between two cylinders of
// the core) and lost 77 % of their volume after 300 s of boundary recovery: the face's
// triangles cover the edge's nodes, so no tetrahedralization has both.
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepTools.hxx>
#include <BRepTools_ReShape.hxx>
#include <BRep_Builder.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>

#include <algorithm>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "cad/CadModel.h"
#include "mesher/pipeline/Pipeline.h"
#include "tests/cad/mesh_volume.h"

namespace aniso::cad {
namespace {

/// A prism along y from y0 to y1 over the polygon `xz` (closed).
TopoDS_Shape prism(const std::vector<std::array<double, 2>>& xz, double y0, double y1) {
  BRepBuilderAPI_MakePolygon p;
  for (const auto& q : xz) p.Add(gp_Pnt(q[0], y0, q[1]));
  p.Close();
  return BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(p.Wire(), true).Face(), gp_Vec(0, y1 - y0, 0)).Shape();
}

/// True when `s` holds an edge met INTERNAL (embedded in its face).
bool hasInternalEdge(const TopoDS_Shape& s) {
  for (TopExp_Explorer e(s, TopAbs_EDGE); e.More(); e.Next())
    if (e.Current().Orientation() == TopAbs_INTERNAL) return true;
  return false;
}

/// A C-shaped prism (a 4 × 4 frame open on the right, arms 1 thick, 2 deep) with a wedge
/// hanging from its upper arm whose edge (x = 3, z = 1, 0.5 ≤ y ≤ 1.5) lies on the lower
/// arm's top face, in none of that face's loops: the fuse of the two, with the contact
/// OpenCASCADE imprinted taken out again. Volume 21. Written as a BREP file.
std::string wedgeTouchingItsFrame() {
  const TopoDS_Shape frame = prism({{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {4, 3}, {4, 4}, {0, 4}}, 0, 2);
  const TopoDS_Shape wedge = prism({{2.5, 3}, {3, 1}, {3.5, 3}}, 0.5, 1.5);
  ShapeUpgrade_UnifySameDomain unify(BRepAlgoAPI_Fuse(frame, wedge).Shape());
  unify.Build();
  TopoDS_Shape s = unify.Shape();
  Handle(BRepTools_ReShape) reshape = new BRepTools_ReShape;
  BRep_Builder b;
  for (TopExp_Explorer x(s, TopAbs_FACE); x.More(); x.Next()) {
    if (!hasInternalEdge(x.Current())) continue;
    TopoDS_Face bare = TopoDS::Face(x.Current().EmptyCopied());
    for (TopoDS_Iterator w(x.Current()); w.More(); w.Next())
      if (!hasInternalEdge(w.Value())) b.Add(bare, w.Value());
    reshape->Replace(x.Current(), bare);
  }
  s = reshape->Apply(s);
  const auto path = std::filesystem::temp_directory_path() / "anisomesh_wedge_touching_frame.brep";
  BRepTools::Write(s, path.string().c_str());
  return path.string();
}

TEST(SelfTouchingSolid, TheEdgeItTouchesItselfAlongIsImprintedAndTheSolidMeshes) {
  const std::string path = wedgeTouchingItsFrame();
  CadModel cad = CadModel::read(path);
  const PrepareReport r = cad.prepare({});
  std::filesystem::remove(path);
  bool rebuilt = false;
  for (const std::string& w : r.warnings) rebuilt = rebuilt || w.find("rebuilt from their faces") != std::string::npos;
  EXPECT_TRUE(rebuilt);
  EXPECT_EQ(r.selfOverlapVolume, 0);
  ASSERT_EQ(cad.summary().solids, 1);
  EXPECT_NEAR(cad.summary().volume, 21, 1e-9);

  const Model model = cad.topology();
  // the wedge's edge is now on the frame's face: used by the wedge's two faces and twice
  // (a slit) by the face it lies on
  std::vector<int> uses(model.edges.size(), 0);
  for (const ModelFace& f : model.faces)
    for (const Loop& l : f.loops)
      for (const EdgeUse& u : l.uses) ++uses[static_cast<std::size_t>(u.edge)];
  EXPECT_EQ(std::count(uses.begin(), uses.end(), 4), 1);

  MeshRequest request;
  request.options.dim = 3;
  const MeshResult m = meshModel(model, request);
  ASSERT_TRUE(m.meshed());
  EXPECT_NEAR(meshVolume(m.volume.mesh), 21, 1e-9);
}

}  // namespace
}  // namespace aniso::cad
