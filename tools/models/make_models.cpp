// make_models: writes anisomesh's own sample models as STEP AP214 through XCAF.
//
//   make_models OUTDIR        build the models and write OUTDIR/{bracket,assembly2,plate,cylinder,cantilever,blocks2,passage,overlap2,cube,holeplate,named_faces}.step and
//                             OUTDIR/{crack,crack_edge}.brep
//   make_models --check FILE  read FILE with STEPCAFControl_Reader and print solids, volume, part names
//
// Output is deterministic: the STEP header (name, time stamp, author, organization,
// originating system) is set to fixed values before writing, so running twice gives
// byte-identical files. All dimensions are in millimetres.
//
// This is a tool, not library code: it uses OpenCASCADE directly.

#include <APIHeaderSection_MakeHeader.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <BOPAlgo_Builder.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBndLib.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepGProp.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepTools.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <StepData_StepModel.hxx>
#include <Standard_Failure.hxx>
#include <TCollection_AsciiString.hxx>
#include <TCollection_ExtendedString.hxx>
#include <TCollection_HAsciiString.hxx>
#include <TDF_Label.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopAbs.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <gp_Pln.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Vertex.hxx>
#include <XCAFApp_Application.hxx>
#include <Quantity_Color.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr const char* kTimeStamp = "2024-01-01T00:00:00";

[[noreturn]] void fail(const std::string& msg) { throw std::runtime_error(msg); }

// ---------------------------------------------------------------- checks

void checkShape(const TopoDS_Shape& s, const std::string& what, int expectedSolids) {
  if (s.IsNull()) fail(what + ": null shape");
  BRepCheck_Analyzer ana(s);
  if (!ana.IsValid()) fail(what + ": BRepCheck_Analyzer reports an invalid shape");
  int solids = 0;
  for (TopExp_Explorer ex(s, TopAbs_SOLID); ex.More(); ex.Next()) ++solids;
  if (solids != expectedSolids)
    fail(what + ": expected " + std::to_string(expectedSolids) + " solid(s), got " + std::to_string(solids));
  GProp_GProps props;
  BRepGProp::VolumeProperties(s, props);
  if (!(props.Mass() > 0.0)) fail(what + ": non-positive volume");
}

// ---------------------------------------------------------------- geometry

TopoDS_Shape box(double x0, double y0, double z0, double dx, double dy, double dz) {
  BRepPrimAPI_MakeBox mk(gp_Pnt(x0, y0, z0), dx, dy, dz);
  mk.Build();
  if (!mk.IsDone()) fail("box construction failed");
  return mk.Shape();
}

TopoDS_Shape cylinder(const gp_Pnt& base, const gp_Dir& axis, double r, double h) {
  BRepPrimAPI_MakeCylinder mk(gp_Ax2(base, axis), r, h);
  mk.Build();
  if (!mk.IsDone()) fail("cylinder construction failed");
  return mk.Shape();
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b, const char* what) {
  BRepAlgoAPI_Cut op(a, b);
  if (!op.IsDone() || op.HasErrors()) fail(std::string(what) + ": boolean cut failed");
  return op.Shape();
}

// Straight edges whose two end points both satisfy `pred`.
std::vector<TopoDS_Edge> edgesWhere(const TopoDS_Shape& s,
                                    const std::function<bool(const gp_Pnt&, const gp_Pnt&)>& pred) {
  std::vector<TopoDS_Edge> out;
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(s, TopAbs_EDGE, edges);
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edges(i));
    if (BRep_Tool::Degenerated(e)) continue;
    if (BRepAdaptor_Curve(e).GetType() != GeomAbs_Line) continue;
    TopoDS_Vertex v1, v2;
    TopExp::Vertices(e, v1, v2);
    if (v1.IsNull() || v2.IsNull()) continue;
    if (pred(BRep_Tool::Pnt(v1), BRep_Tool::Pnt(v2))) out.push_back(e);
  }
  return out;
}

bool near(double a, double b) { return std::abs(a - b) < 1e-4; }

// L-shaped bracket (mm):
//   base plate   x 0..80, y 0..50, z 0..8
//   upright      x 0..8,  y 0..50, z 0..60   (overlaps the base's end; overall height 60)
//   fillets      r 6 on the inner corner edge of the L (x=8, z=8, along y),
//                r 10 on the two outer vertical edges at the free end of the base (x=80)
//   holes        two d 8 through the base at (55,15) and (55,35), along z;
//                one d 12 through the upright at (y 25, z 40), along x
TopoDS_Shape makeBracket() {
  const double L = 80, W = 50, T = 8, H = 60;
  TopoDS_Shape base = box(0, 0, 0, L, W, T);
  TopoDS_Shape upright = box(0, 0, 0, T, W, H);

  BRepAlgoAPI_Fuse fuse(base, upright);
  if (!fuse.IsDone() || fuse.HasErrors()) fail("bracket: fuse failed");
  // Merge the coplanar faces the fuse leaves split (bottom, back, sides).
  ShapeUpgrade_UnifySameDomain unify(fuse.Shape(), Standard_True, Standard_True, Standard_True);
  unify.Build();
  TopoDS_Shape l = unify.Shape();

  // Inner corner of the L: the edge along y at x = T, z = T.
  auto inner = edgesWhere(l, [&](const gp_Pnt& a, const gp_Pnt& b) {
    return near(a.X(), T) && near(b.X(), T) && near(a.Z(), T) && near(b.Z(), T);
  });
  // Outer vertical edges at the free end of the base: along z at x = L.
  auto outer = edgesWhere(l, [&](const gp_Pnt& a, const gp_Pnt& b) {
    return near(a.X(), L) && near(b.X(), L) && near(a.Y(), b.Y()) && !near(a.Z(), b.Z());
  });
  if (inner.size() != 1) fail("bracket: expected 1 inner corner edge, found " + std::to_string(inner.size()));
  if (outer.size() != 2) fail("bracket: expected 2 outer vertical edges, found " + std::to_string(outer.size()));

  BRepFilletAPI_MakeFillet fillet(l);
  fillet.Add(6.0, inner[0]);
  for (const auto& e : outer) fillet.Add(10.0, e);
  fillet.Build();
  if (!fillet.IsDone()) fail("bracket: fillet failed");
  TopoDS_Shape s = fillet.Shape();

  const gp_Dir Z(0, 0, 1), X(1, 0, 0);
  s = cut(s, cylinder(gp_Pnt(55, 15, -1), Z, 4.0, T + 2), "bracket base hole 1");
  s = cut(s, cylinder(gp_Pnt(55, 35, -1), Z, 4.0, T + 2), "bracket base hole 2");
  s = cut(s, cylinder(gp_Pnt(-1, 25, 40), X, 6.0, T + 2), "bracket upright hole");
  return s;
}

// Thin plate 100 x 60 x 1 with one d 20 through-hole at the centre.
TopoDS_Shape makePlate() {
  TopoDS_Shape p = box(0, 0, 0, 100, 60, 1);
  return cut(p, cylinder(gp_Pnt(50, 30, -1), gp_Dir(0, 0, 1), 10.0, 3.0), "plate hole");
}

// Cylinder r 10, h 40, axis z from the origin.
TopoDS_Shape makeCylinder() { return cylinder(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1), 10.0, 40.0); }

// Cantilever 100 x 10 x 10 from the origin. OCCT's box orders its faces x = 0, x = 100,
// y = 0, y = 10, z = 0, z = 10: FACE1 is the clamped end, FACE2 the loaded end.
TopoDS_Shape makeCantilever() { return box(0, 0, 0, 100, 10, 10); }

/// Cube 10 × 10 × 10 from the origin, for the adapt tests (issue 19).
TopoDS_Shape makeCube() { return box(0, 0, 0, 10, 10, 10); }

/// Plate 200 × 100 × 5 from the origin with a Ø20 through-hole at its centre (100, 50): the
/// stress concentration benchmark of the adapt command (tools/bench/adapt_holeplate.py;
/// d/W = 0.2, Peterson's net-section K_t 2.51). OCCT's box faces x = 0 and x = 200 come first.
TopoDS_Shape makeHolePlate() {
  TopoDS_Shape p = box(0, 0, 0, 200, 100, 5);
  return cut(p, cylinder(gp_Pnt(100, 50, -1), gp_Dir(0, 0, 1), 10.0, 7.0), "holeplate hole");
}


// ---------------------------------------------------------------- XCAF / STEP

Handle(TDocStd_Document) newDoc() {
  Handle(XCAFApp_Application) app = XCAFApp_Application::GetApplication();
  Handle(TDocStd_Document) doc;
  app->NewDocument("MDTV-XCAF", doc);
  if (doc.IsNull()) fail("cannot create an XCAF document");
  return doc;
}

void setName(const TDF_Label& l, const char* name) {
  TDataStd_Name::Set(l, TCollection_ExtendedString(name));
}

// `colors`: the document's colours are written too (STYLED_ITEMs), and the names of
// sub-shape labels (faces) as the names of their STEP representation items.
void writeStep(const Handle(TDocStd_Document)& doc, const std::filesystem::path& path, bool colors = false) {
  if (!Interface_Static::SetIVal("write.stepcaf.subshapes.name", colors ? 1 : 0))
    fail("cannot set write.stepcaf.subshapes.name");
  STEPCAFControl_Writer writer;
  writer.SetNameMode(Standard_True);
  writer.SetColorMode(colors ? Standard_True : Standard_False);
  writer.SetLayerMode(Standard_False);
  writer.SetPropsMode(Standard_False);
  if (!writer.Transfer(doc, STEPControl_AsIs)) fail(path.string() + ": XCAF transfer failed");

  Handle(StepData_StepModel) model = writer.ChangeWriter().Model();
  if (model.IsNull()) fail(path.string() + ": no STEP model after transfer");
  APIHeaderSection_MakeHeader header(model);
  if (!header.HasFn()) fail(path.string() + ": STEP model has no FILE_NAME header");
  header.SetName(new TCollection_HAsciiString(path.filename().string().c_str()));
  header.SetTimeStamp(new TCollection_HAsciiString(kTimeStamp));
  header.SetAuthorValue(1, new TCollection_HAsciiString("anisomesh"));
  header.SetOrganizationValue(1, new TCollection_HAsciiString("anisomesh"));
  header.SetOriginatingSystem(new TCollection_HAsciiString("anisomesh make_models"));
  header.SetAuthorisation(new TCollection_HAsciiString(""));
  header.Apply(model);

  if (writer.Write(path.string().c_str()) != IFSelect_RetDone) fail(path.string() + ": STEP write failed");
  std::cout << "wrote " << path.string() << "\n";
}

// One shape as one named part (no check of what it is).
void writePart(const TopoDS_Shape& s, const char* name, const std::filesystem::path& path) {
  Handle(TDocStd_Document) doc = newDoc();
  Handle(XCAFDoc_ShapeTool) st = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_Label l = st->AddShape(s, Standard_False);
  if (l.IsNull()) fail(std::string(name) + ": cannot add shape to the document");
  setName(l, name);
  writeStep(doc, path);
}

void writeSinglePart(const TopoDS_Shape& s, const char* name, const std::filesystem::path& path) {
  checkShape(s, name, 1);
  writePart(s, name, path);
}

// An assembly of two components (each its own part with its shape at the origin, placed by
// the component's location), checked for two solids, written as STEP.
void writeTwoParts(const std::filesystem::path& path, const char* assemblyName, const TopoDS_Shape& a,
                   const char* nameA, const TopLoc_Location& locA, const TopoDS_Shape& b, const char* nameB,
                   const TopLoc_Location& locB) {
  Handle(TDocStd_Document) doc = newDoc();
  Handle(XCAFDoc_ShapeTool) st = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_Label assy = st->NewShape();
  setName(assy, assemblyName);
  TDF_Label lA = st->AddShape(a, Standard_False);
  TDF_Label lB = st->AddShape(b, Standard_False);
  setName(lA, nameA);
  setName(lB, nameB);
  TDF_Label cA = st->AddComponent(assy, lA, locA);
  TDF_Label cB = st->AddComponent(assy, lB, locB);
  if (cA.IsNull() || cB.IsNull()) fail(std::string(assemblyName) + ": cannot add components");
  setName(cA, nameA);
  setName(cB, nameB);
  st->UpdateAssemblies();
  checkShape(st->GetShape(assy), assemblyName, 2);
  writeStep(doc, path);
}

// Two-part assembly: BLOCK (20 x 20 x 10) sits centred on BASE (40 x 40 x 10).
// BLOCK's bottom face (20 x 20) lies entirely inside BASE's top face (40 x 40).
// Each part is defined at the origin; the components place them.
void writeAssembly2(const std::filesystem::path& path) {
  TopoDS_Shape base = box(0, 0, 0, 40, 40, 10);
  TopoDS_Shape block = box(0, 0, 0, 20, 20, 10);
  checkShape(base, "BASE", 1);
  checkShape(block, "BLOCK", 1);

  gp_Trsf tBlock;
  tBlock.SetTranslation(gp_Vec(10, 10, 10));
  // The placed pair, checked as it will appear in the file.
  {
    TopoDS_Shape placed = block.Moved(TopLoc_Location(tBlock));
    checkShape(placed, "BLOCK (placed)", 1);
    Bnd_Box bb;
    BRepBndLib::Add(placed, bb);
    double x0, y0, z0, x1, y1, z1;
    bb.Get(x0, y0, z0, x1, y1, z1);
    if (std::abs(z0 - 10.0) > 1e-3) fail("assembly2: BLOCK does not sit on BASE");
  }

  writeTwoParts(path, "ASSEMBLY2", base, "BASE", TopLoc_Location(), block, "BLOCK", TopLoc_Location(tBlock));
}

// Two cubes 10 x 10 x 10 side by side along x, sharing the face x = 10 (two parts of one
// shape, placed by their components): at the defaults (h = half the diagonal, 12.2) each
// square face is two triangles, the coarse surface of mesher/volume/CoarseSolids.h.
void writeBlocks2(const std::filesystem::path& path) {
  // two shapes (one would be one part for XCAF)
  TopoDS_Shape left = box(0, 0, 0, 10, 10, 10), right = box(0, 0, 0, 10, 10, 10);
  checkShape(left, "LEFT", 1);
  checkShape(right, "RIGHT", 1);
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(10, 0, 0));
  writeTwoParts(path, "BLOCKS2", left, "LEFT", TopLoc_Location(), right, "RIGHT", TopLoc_Location(shift));
}

// Two cubes 10 x 10 x 10 side by side along x, as blocks2 (LEFT x 0..10, RIGHT x 10..20,
// sharing the face x = 10), whose faces carry STEP names and colours (issue 17): LEFT's
// x = 0 face "fixed" (red), RIGHT's x = 20 face "load face" (blue), both tops z = 10
// "top" (one name, two parts), LEFT's bottom z = 0 a colour only (grey); RIGHT the part
// colour green (not a face colour of its faces). OCCT's box order: FACE1 x = 0, FACE2
// x = 10, FACE3/4 y = 0/10, FACE5/6 z = 0/10.
void writeNamedFaces(const std::filesystem::path& path) {
  TopoDS_Shape left = box(0, 0, 0, 10, 10, 10), right = box(0, 0, 0, 10, 10, 10);
  checkShape(left, "LEFT", 1);
  checkShape(right, "RIGHT", 1);
  Handle(TDocStd_Document) doc = newDoc();
  Handle(XCAFDoc_ShapeTool) st = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  Handle(XCAFDoc_ColorTool) ct = XCAFDoc_DocumentTool::ColorTool(doc->Main());
  TDF_Label assy = st->NewShape();
  setName(assy, "NAMED_FACES");
  TDF_Label lL = st->AddShape(left, Standard_False), lR = st->AddShape(right, Standard_False);
  setName(lL, "LEFT");
  setName(lR, "RIGHT");
  const auto tagFace = [&](const TDF_Label& part, const TopoDS_Shape& solid, int face, const char* name,
                           const char* hex) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    const TDF_Label sub = st->AddSubShape(part, faces(face));
    if (sub.IsNull()) fail(std::string("named_faces: cannot add face ") + std::to_string(face));
    if (name) setName(sub, name);
    Quantity_Color c;
    if (hex && !Quantity_Color::ColorFromHex(hex, c)) fail(std::string("named_faces: bad colour ") + hex);
    if (hex) ct->SetColor(sub, c, XCAFDoc_ColorSurf);
  };
  tagFace(lL, left, 1, "fixed", "#FF0000");
  tagFace(lL, left, 6, "top", nullptr);
  tagFace(lL, left, 5, nullptr, "#808080");
  tagFace(lR, right, 2, "load face", "#0000FF");
  tagFace(lR, right, 6, "top", nullptr);
  Quantity_Color green;
  Quantity_Color::ColorFromHex("#00FF00", green);
  ct->SetColor(lR, green, XCAFDoc_ColorSurf);
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(10, 0, 0));
  const TDF_Label cL = st->AddComponent(assy, lL, TopLoc_Location());
  const TDF_Label cR = st->AddComponent(assy, lR, TopLoc_Location(shift));
  if (cL.IsNull() || cR.IsNull()) fail("named_faces: cannot add components");
  setName(cL, "LEFT");
  setName(cR, "RIGHT");
  st->UpdateAssemblies();
  checkShape(st->GetShape(assy), "NAMED_FACES", 2);
  writeStep(doc, path, /*colors*/ true);
}

// A turbine-passage-like surface model (no solid): the closed shell of a B-spline patch
// swept 20 mm along z (5 faces: the patch twice, three extruded sides; the collapsed edge
// sweeps to nothing). The patch (x 0..100, y 0..60, a cambered blade-like bump of 8 mm) is
// bicubic on 10 x 8 control points and has the two defects of fitted CAD surfaces that make
// the curvature spurious:
//   - a degenerate corner: the whole v = 0 row of control points is collapsed onto the
//     corner (0, 0), so the patch is a fan from that point (p_u = 0 along the row, the
//     normal undefined there, the point curvature next to it spurious and unbounded);
//   - noise: every interior control point moved along z by a deterministic pseudo-random
//     amount of up to 0.02 mm (1e-4 of the model's size).
// Measured (issue 20): at --hmax-rel 0.02 --curvature-ratio 0.26 --anisotropy 1 the build
// before the robust curvature never left the control spaces (> 120 s, 1 GB).
TopoDS_Shape makePassage() {
  const int nu = 10, nv = 8;
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  unsigned seed = 12345u;
  auto noise = [&seed] {  // deterministic LCG in [-1, 1]
    seed = seed * 1664525u + 1013904223u;
    return 2.0 * ((seed >> 8) & 0xFFFF) / 65535.0 - 1.0;
  };
  for (int i = 1; i <= nu; ++i)
    for (int j = 1; j <= nv; ++j) {
      const double x = 100.0 * (i - 1) / (nu - 1), y = 60.0 * (j - 1) / (nv - 1);
      const double camber = 8.0 * std::sin(M_PI * x / 100.0) * (0.5 + 0.5 * y / 60.0);
      const bool interior = i > 1 && i < nu && j > 1 && j < nv;
      poles(i, j) = gp_Pnt(x, y, camber + (interior ? 0.02 * noise() : 0.0));
    }
  for (int i = 2; i <= nu; ++i) poles(i, 1) = poles(1, 1);  // the collapsed row
  auto knots = [](int n, TColStd_Array1OfReal& k, TColStd_Array1OfInteger& m) {
    const int spans = n - 3;
    for (int i = 0; i <= spans; ++i) {
      k(i + 1) = double(i) / spans;
      m(i + 1) = (i == 0 || i == spans) ? 4 : 1;
    }
  };
  TColStd_Array1OfReal uk(1, nu - 2), vk(1, nv - 2);
  TColStd_Array1OfInteger um(1, nu - 2), vm(1, nv - 2);
  knots(nu, uk, um);
  knots(nv, vk, vm);
  Handle(Geom_BSplineSurface) surf = new Geom_BSplineSurface(poles, uk, vk, um, vm, 3, 3);
  BRepBuilderAPI_MakeFace mf(surf, 1e-6);
  if (!mf.IsDone()) fail("passage: face construction failed");
  BRepPrimAPI_MakePrism prism(mf.Face(), gp_Vec(0, 0, 20));
  prism.Build();
  if (!prism.IsDone()) fail("passage: sweep failed");
  TopExp_Explorer ex(prism.Shape(), TopAbs_SHELL);
  if (!ex.More()) fail("passage: no shell");
  const TopoDS_Shape shell = ex.Current();
  if (!BRepCheck_Analyzer(shell).IsValid()) fail("passage: BRepCheck_Analyzer reports an invalid shell");
  return shell;
}

// Two cubes 10 x 10 x 10 overlapping by half along x: A at the origin, B at (5, 0, 0). Their
// common region (5 x 10 x 10, volume 500) is what --overlaps merge meshes once; the union's
// volume is 1500 and its outer area 2 * (15 * 10) * 2 + 2 * 10 * 10 = 800.
void writeOverlap2(const std::filesystem::path& path) {
  TopoDS_Shape a = box(0, 0, 0, 10, 10, 10), b = box(0, 0, 0, 10, 10, 10);
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(5, 0, 0));
  writeTwoParts(path, "OVERLAP2", a, "BOX_A", TopLoc_Location(), b, "BOX_B", TopLoc_Location(shift));
}

// A 10 mm cube with a face inside (issue 20, embedded faces): the square x, y in [lo, hi]
// at z = 5, joined to the cube by OCCT's general fuse, which keeps it as an INTERNAL face
// of the solid in a shell of its own (zero thickness: a crack). lo < 0 or hi > 10 make the
// face reach the cube's sides (an edge crack, imprinted on them).
TopoDS_Shape makeCrackedCube(double lo, double hi) {
  const TopoDS_Shape cube = box(0, 0, 0, 10, 10, 10);
  const TopoDS_Face crack = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 5), gp_Dir(0, 0, 1)), lo, hi, lo, hi).Face();
  BOPAlgo_Builder fuse;
  fuse.AddArgument(cube);
  fuse.AddArgument(crack);
  fuse.Perform();
  if (fuse.HasErrors()) fail("cracked cube: general fuse failed");
  TopExp_Explorer solid(fuse.Shape(), TopAbs_SOLID);
  if (!solid.More()) fail("cracked cube: no solid");
  return solid.Current();
}

void writeBrep(const TopoDS_Shape& s, const char* what, const std::filesystem::path& path) {
  checkShape(s, what, 1);
  if (!BRepTools::Write(s, path.string().c_str())) fail(std::string("cannot write ") + path.string());
  std::cout << "wrote " << path.string() << "\n";
}

// ---------------------------------------------------------------- --check

// Round-off below the printed precision would otherwise show up as "-0.00".
double tidy(double v) { return std::abs(v) < 5e-3 ? 0.0 : v; }

std::string labelName(const TDF_Label& l) {
  Handle(TDataStd_Name) n;
  if (!l.FindAttribute(TDataStd_Name::GetID(), n)) return "<unnamed>";
  return TCollection_AsciiString(n->Get()).ToCString();
}

int checkFile(const char* file) {
  STEPCAFControl_Reader reader;
  reader.SetNameMode(Standard_True);
  if (reader.ReadFile(file) != IFSelect_RetDone) fail(std::string(file) + ": cannot read STEP file");
  Handle(TDocStd_Document) doc = newDoc();
  if (!reader.Transfer(doc)) fail(std::string(file) + ": XCAF transfer from STEP failed");

  Handle(XCAFDoc_ShapeTool) st = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence roots;
  st->GetFreeShapes(roots);
  if (roots.IsEmpty()) fail(std::string(file) + ": no shapes");

  int totalSolids = 0;
  double totalVolume = 0;
  Bnd_Box bb;
  std::vector<std::string> parts;
  std::vector<std::string> details;

  // Walk the assembly structure down to the simple shapes (parts).
  std::function<void(const TDF_Label&, const TopLoc_Location&, int)> walk =
      [&](const TDF_Label& l, const TopLoc_Location& loc, int depth) {
        if (st->IsAssembly(l)) {
          details.push_back(std::string(2 * depth, ' ') + "assembly " + labelName(l));
          TDF_LabelSequence comps;
          st->GetComponents(l, comps);
          for (int i = 1; i <= comps.Length(); ++i) {
            TDF_Label ref;
            if (!st->GetReferredShape(comps(i), ref)) continue;
            walk(ref, loc * st->GetLocation(comps(i)), depth + 1);
          }
          return;
        }
        TopoDS_Shape s = st->GetShape(l).Moved(loc);
        int solids = 0;
        for (TopExp_Explorer ex(s, TopAbs_SOLID); ex.More(); ex.Next()) ++solids;
        GProp_GProps props;
        BRepGProp::VolumeProperties(s, props);
        BRepBndLib::AddOptimal(s, bb, Standard_False, Standard_False);
        Bnd_Box pb;
        BRepBndLib::AddOptimal(s, pb, Standard_False, Standard_False);
        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(s, TopAbs_FACE, faces);
        double x0, y0, z0, x1, y1, z1;
        pb.Get(x0, y0, z0, x1, y1, z1);
        totalSolids += solids;
        totalVolume += props.Mass();
        parts.push_back(labelName(l));
        char buf[256];
        std::snprintf(buf, sizeof buf, "part %s: solids %d, faces %d, volume %.3f, bbox [%.2f %.2f %.2f]-[%.2f %.2f %.2f], valid %s",
                      labelName(l).c_str(), solids, faces.Extent(), props.Mass(), tidy(x0), tidy(y0),
                      tidy(z0), tidy(x1), tidy(y1), tidy(z1),
                      BRepCheck_Analyzer(s).IsValid() ? "yes" : "NO");
        details.push_back(std::string(2 * depth, ' ') + buf);
      };
  for (int i = 1; i <= roots.Length(); ++i) walk(roots(i), TopLoc_Location(), 0);

  double x0, y0, z0, x1, y1, z1;
  bb.Get(x0, y0, z0, x1, y1, z1);
  std::string names;
  for (const auto& p : parts) names += (names.empty() ? "" : ",") + p;
  std::printf("%s: solids %d, volume %.3f mm^3, bbox [%.2f %.2f %.2f]-[%.2f %.2f %.2f], parts %s\n", file,
              totalSolids, totalVolume, tidy(x0), tidy(y0), tidy(z0), tidy(x1), tidy(y1), tidy(z1),
              names.c_str());
  for (const auto& d : details) std::printf("  %s\n", d.c_str());
  return totalSolids > 0 ? 0 : 1;
}

// ---------------------------------------------------------------- main

void silenceOcct() {
  // OCCT's default messenger prints transfer statistics to stdout; keep stdout to
  // one line per file written.
  Handle(Message_Messenger) m = Message::DefaultMessenger();
  m->RemovePrinters(STANDARD_TYPE(Message_Printer));
}

void configureStep() {
  STEPCAFControl_Controller::Init();
  if (!Interface_Static::SetCVal("write.step.schema", "AP214IS")) fail("cannot set write.step.schema");
  if (!Interface_Static::SetCVal("write.step.unit", "MM")) fail("cannot set write.step.unit");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    silenceOcct();
    configureStep();
    if (argc == 3 && std::string(argv[1]) == "--check") return checkFile(argv[2]);
    if (argc != 2 || argv[1][0] == '-') {
      std::cerr << "usage: make_models OUTDIR\n       make_models --check FILE\n";
      return 2;
    }
    std::filesystem::path out(argv[1]);
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (!std::filesystem::is_directory(out)) fail("cannot create output directory " + out.string());

    writeSinglePart(makeBracket(), "BRACKET", out / "bracket.step");
    writeAssembly2(out / "assembly2.step");
    writeSinglePart(makePlate(), "PLATE", out / "plate.step");
    writeSinglePart(makeCylinder(), "CYLINDER", out / "cylinder.step");
    writeSinglePart(makeCantilever(), "CANTILEVER", out / "cantilever.step");
    writeBlocks2(out / "blocks2.step");
    writePart(makePassage(), "PASSAGE", out / "passage.step");  // a surface model: no solid
    writeOverlap2(out / "overlap2.step");
    writeSinglePart(makeCube(), "CUBE", out / "cube.step");
    writeSinglePart(makeHolePlate(), "HOLEPLATE", out / "holeplate.step");
    writeNamedFaces(out / "named_faces.step");
    // STEP (OCCT's writer) drops a solid's INTERNAL faces: the cracked cubes are BREP.
    writeBrep(makeCrackedCube(2, 8), "cracked cube", out / "crack.brep");  // a crack inside
    writeBrep(makeCrackedCube(-1, 5), "edge crack", out / "crack_edge.brep");  // open at two sides
    return 0;
  } catch (const Standard_Failure& e) {
    std::cerr << "make_models: OCCT exception: " << e.GetMessageString() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "make_models: " << e.what() << "\n";
  }
  return 1;
}
