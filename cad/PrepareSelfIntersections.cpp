#include <BOPAlgo_CheckerSI.hxx>
#include <BOPAlgo_MakerVolume.hxx>
#include <BOPDS_DS.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>

#include <cmath>
#include <string>
#include <vector>

#include "cad/detail/FaceTags.h"
#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {
namespace {

/// The rebuilt pieces must add up to the solid's volume within this fraction (measured:
/// Push_SMD_6.2x6.2mm solid 1, 109.684 -> 109.682; water_module solids 3, 8, 10 the same to
/// 2e-5).
constexpr double kRebuildVolumeRel = 5e-3;
/// A shell of a rebuilt piece enclosing less than this fraction of the piece's volume is
/// a sheet, dropped.
constexpr double kFlatShellRel = 1e-9;

/// Interferences the self-crossing check looks for: vertex/vertex, vertex/edge, edge/edge,
/// vertex/face and edge/face (level 4 of BOPAlgo_CheckerSI). Face/face intersection (level
/// 5, the default of BOPAlgo_ArgumentAnalyzer) is left out: it intersects every pair of
/// faces whose boxes overlap, neighbours included, and cost 158 s on one 124-face solid
/// (MiniSB_adxl_mount, not crossing) against 0.6 s here. Two faces that cross have an edge
/// of one through the other unless their intersection curve closes inside both faces; on
/// every solid of ../shared/assemblies the two levels gave the same verdict.
constexpr int kSelfCheckLevel = 4;

bool selfInterfering(const TopoDS_Shape& solid) {
  BOPAlgo_CheckerSI checker;
  TopTools_ListOfShape arguments;
  arguments.Append(solid);
  checker.SetArguments(arguments);
  checker.SetLevelOfCheck(kSelfCheckLevel);
  checker.SetNonDestructive(true);
  checker.SetRunParallel(false);
  checker.Perform();
  return checker.HasErrors() || checker.DS().Interferences().Extent() > 0;
}

/// True when an edge of the piece bounds more than two distinct faces: a solid touching
/// itself (hinge_R_assy's slit), which the rebuild does not make any better for the mesher.
bool nonManifold(const TopoDS_Shape& piece) {
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(piece, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  for (int i = 1; i <= edgeFaces.Extent(); ++i) {
    TopTools_IndexedMapOfShape distinct;
    for (const TopoDS_Shape& f : edgeFaces(i)) distinct.Add(f);
    if (distinct.Extent() > 2) return true;
  }
  return false;
}

/// The piece without its shells that enclose no volume (sheets MakerVolume leaves inside a
/// piece where faces crossed: water_module's solid 3 came with four, touching its outer
/// shell along non-manifold edges).
TopoDS_Shape withoutFlatShells(const TopoDS_Shape& piece, double pieceVolume) {
  std::vector<TopoDS_Shape> kept;
  int shells = 0;
  for (TopExp_Explorer x(piece, TopAbs_SHELL); x.More(); x.Next()) {
    ++shells;
    BRepBuilderAPI_MakeSolid one(TopoDS::Shell(x.Current()));
    if (one.IsDone() && std::abs(solidVolume(one.Shape())) > kFlatShellRel * std::abs(pieceVolume))
      kept.push_back(x.Current());
  }
  if (kept.empty() || static_cast<int>(kept.size()) == shells) return piece;
  BRep_Builder b;
  TopoDS_Solid solid;
  b.MakeSolid(solid);
  for (const TopoDS_Shape& sh : kept) b.Add(solid, sh);
  return solid;
}

/// The solids with positive volume MakerVolume builds from the solid's faces (without
/// their flat shells); empty when they do not add up to its volume or one of them is not
/// manifold. `history`: what became of the faces.
std::vector<TopoDS_Shape> rebuilt(const TopoDS_Shape& solid, Handle(BRepTools_History)& history) {
  BOPAlgo_MakerVolume mv;
  TopTools_ListOfShape faces;
  for (TopExp_Explorer f(solid, TopAbs_FACE); f.More(); f.Next()) faces.Append(f.Current());
  mv.SetArguments(faces);
  mv.SetRunParallel(false);
  mv.SetIntersect(true);
  mv.Perform();
  if (mv.HasErrors()) return {};
  history = mv.History();
  TopTools_IndexedMapOfShape out;
  TopExp::MapShapes(mv.Shape(), TopAbs_SOLID, out);
  std::vector<TopoDS_Shape> pieces;
  double total = 0;
  for (int k = 1; k <= out.Extent(); ++k)
    if (const double v = solidVolume(out(k)); v > 0) {
      const TopoDS_Shape piece = withoutFlatShells(out(k), v);
      if (nonManifold(piece)) return {};
      pieces.push_back(piece);
      total += v;
    }
  const double before = std::abs(solidVolume(solid));
  if (pieces.empty() || std::abs(total - before) > kRebuildVolumeRel * before) return {};
  // the pieces must be as valid as the solid (KiCad battery holders: the pegs' tips meet
  // their cylinders at coincident but distinct vertices; MakerVolume dropped the tips and
  // left the cylinders' loops open by a period in (u, v), within the volume check above)
  BRep_Builder b;
  TopoDS_Compound all;
  b.MakeCompound(all);
  for (const TopoDS_Shape& p : pieces) b.Add(all, p);
  if (!BRepCheck_Analyzer(all).IsValid() && BRepCheck_Analyzer(solid).IsValid()) return {};
  return pieces;
}

}  // namespace

void rebuildSelfIntersecting(CadModel::Impl& impl, PrepareReport& report) {
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(impl.shape, TopAbs_SOLID, solids);
  std::vector<std::vector<TopoDS_Shape>> replacement(static_cast<std::size_t>(solids.Extent()) + 1);
  std::vector<Handle(BRepTools_History)> history(replacement.size());
  std::string fixed;
  for (int i = 1; i <= solids.Extent(); ++i) {
    try {
      if (!selfInterfering(solids(i))) continue;
      replacement[static_cast<std::size_t>(i)] = rebuilt(solids(i), history[static_cast<std::size_t>(i)]);
    } catch (const Standard_Failure&) {
      continue;  // left as it is
    }
    if (!replacement[static_cast<std::size_t>(i)].empty())
      fixed += (fixed.empty() ? "" : ", ") + std::to_string(i) + " \"" + impl.solidName(solids(i), i) + "\"";
  }
  if (fixed.empty()) return;
  // the new shape: the solids in order, each rebuilt one replaced by its pieces, then the
  // faces in no solid (as the fragmenting step assembles its result)
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  for (int i = 1; i <= solids.Extent(); ++i) {
    const std::vector<TopoDS_Shape>& pieces = replacement[static_cast<std::size_t>(i)];
    if (pieces.empty()) {
      b.Add(c, solids(i));
      continue;
    }
    const TopoDS_Shape key = solids(i).Located(TopLoc_Location());
    for (const TopoDS_Shape& p : pieces) {
      b.Add(c, p);
      if (impl.nameIndex.IsBound(key)) impl.nameIndex.Bind(p.Located(TopLoc_Location()), impl.nameIndex.Find(key));
    }
  }
  addLooseFaces(impl.shape, solids, c);
  impl.shape = c;
  for (int i = 1; i <= solids.Extent(); ++i)
    if (!replacement[static_cast<std::size_t>(i)].empty())
      carryFaceTags(impl, solids(i), [&h = history[static_cast<std::size_t>(i)]](const TopoDS_Shape& f) {
        return historyImages(h, f);
      });
  dropStaleFaceTags(impl);
  report.warnings.push_back("solid(s) " + fixed +
                            " had faces crossing one another: rebuilt from their faces, split where they cross");
}

}  // namespace aniso::cad::detail
