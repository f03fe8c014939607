#include <BOPAlgo_CheckerSI.hxx>
#include <BOPAlgo_MakerVolume.hxx>
#include <BOPDS_DS.hxx>
#include <BRepBndLib.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepTools.hxx>
#include <Bnd_Box.hxx>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <OSD_Parallel.hxx>
#include <gp_Lin.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <TopoDS_Shell.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Solid.hxx>

#include <cmath>
#include <map>
#include <optional>
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
/// A solid that only touches itself (an edge of it lying on one of its faces, shared by
/// none) is rebuilt as one piece with the same volume to within this fraction: the rebuild
/// only imprints the contact (KiCad toroid: 981.190335 -> 981.190384). MakerVolume losing
/// more than that (a battery holder's clip, -0.12 %) is not an imprint.
constexpr double kImprintVolumeRel = 1e-5;
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

/// `parallel`: the check's own parallel mode (its pairs of sub-shapes in threads), for a
/// model of one solid; several solids are checked side by side instead (selfInterferingSolids).
bool selfInterfering(const TopoDS_Shape& solid, bool parallel) {
  BOPAlgo_CheckerSI checker;
  TopTools_ListOfShape arguments;
  arguments.Append(solid);
  checker.SetArguments(arguments);
  checker.SetLevelOfCheck(kSelfCheckLevel);
  checker.SetNonDestructive(true);
  checker.SetRunParallel(parallel);
  checker.Perform();
  return checker.HasErrors() || checker.DS().Interferences().Extent() > 0;
}

/// selfInterfering for solids(1..n), in threads: the check is most of the preparation of a
/// single part (U_Joint_2: 4.1 s of 15 s serial). The threads are OpenCASCADE's own pool
/// (OSD_ThreadPool), not TBB's: this runs in the forked child of runPrepareStep, where a TBB
/// pool the parent had started (a Python program may have) would wait for workers that do
/// not exist; the parent process never starts OpenCASCADE's pool. Instances of one part
/// (the same TShape placed by different locations: an assembly's screws) are checked once:
/// a rigid placement crosses nothing. The verdicts do not depend on the threads.
/// Result: 1 crossing, 0 not, -1 the check failed (left as is).
std::vector<int> selfInterferingSolids(const TopTools_IndexedMapOfShape& solids) {
  const int n = solids.Extent();
  std::vector<int> first(static_cast<std::size_t>(n) + 1, 0);  // the instance checked for solid i
  std::vector<int> checked;
  std::map<const TopoDS_TShape*, int> seen;
  for (int i = 1; i <= n; ++i) {
    const auto [it, added] = seen.emplace(solids(i).TShape().get(), i);
    first[static_cast<std::size_t>(i)] = it->second;
    if (added) checked.push_back(i);
  }
  std::vector<int> verdict(static_cast<std::size_t>(n) + 1, 0);
  OSD_Parallel::SetUseOcctThreads(true);
  const int m = static_cast<int>(checked.size());
  OSD_Parallel::For(0, m, [&](int k) {
    const int i = checked[static_cast<std::size_t>(k)];
    try {
      verdict[static_cast<std::size_t>(i)] = selfInterfering(solids(i), m == 1) ? 1 : 0;
    } catch (const Standard_Failure&) {
      verdict[static_cast<std::size_t>(i)] = -1;
    }
  });
  for (int i = 1; i <= n; ++i) verdict[static_cast<std::size_t>(i)] = verdict[static_cast<std::size_t>(first[static_cast<std::size_t>(i)])];
  return verdict;
}

/// True when an edge of the piece bounds more than two distinct faces: a solid touching
/// itself along that edge.
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

/// Ray directions for the winding number: not along a coordinate axis or diagonal (CAD
/// faces and edges are), and two of them, which must agree.
constexpr double kRayDirections[2][3] = {{0.5734, 0.3917, 0.7196}, {-0.4421, 0.8139, 0.3770}};
/// Inward step from a face of a piece to a point inside it, relative to the piece's box.
constexpr double kInsideStepRel = 1e-4;

/// A point strictly inside `piece`: a step inward from the middle of one of its faces,
/// confirmed by the classifier; none when no face gives one.
std::optional<gp_Pnt> pointInside(const TopoDS_Shape& piece) {
  Bnd_Box box;
  BRepBndLib::Add(piece, box);
  if (box.IsVoid()) return std::nullopt;
  const double step = kInsideStepRel * std::sqrt(box.SquareExtent());
  BRepClass3d_SolidClassifier classifier(piece);
  for (TopExp_Explorer x(piece, TopAbs_FACE); x.More(); x.Next()) {
    const TopoDS_Face& f = TopoDS::Face(x.Current());
    double u0, u1, v0, v1;
    BRepTools::UVBounds(f, u0, u1, v0, v1);
    const BRepGProp_Face props(f);  // the normal follows the face's orientation: outward
    for (const double w : {0.5, 0.37, 0.63}) {
      gp_Pnt p;
      gp_Vec n;
      props.Normal(u0 + w * (u1 - u0), v0 + w * (v1 - v0), p, n);
      if (n.Magnitude() <= 0) continue;
      const gp_Pnt q = p.Translated(-step * n.Normalized());
      classifier.Perform(q, step * 1e-3);
      if (classifier.State() == TopAbs_IN) return q;
    }
  }
  return std::nullopt;
}

/// How many times the faces of `solid` wind around `p`: the signed count of their crossings
/// by a ray from p (+1 leaving through a face, −1 entering), along each of kRayDirections;
/// none when the two rays disagree (a ray grazing an edge).
std::optional<int> windingNumber(const TopoDS_Shape& solid, const gp_Pnt& p) {
  std::optional<int> out;
  for (const auto& d : kRayDirections) {
    const gp_Dir dir(d[0], d[1], d[2]);
    IntCurvesFace_ShapeIntersector hits;
    hits.Load(solid, Precision::Confusion());
    hits.Perform(gp_Lin(p, dir), 0.0, Precision::Infinite());
    if (!hits.IsDone()) return std::nullopt;
    int w = 0;
    for (int i = 1; i <= hits.NbPnt(); ++i) {
      if (hits.WParameter(i) <= 0) continue;
      BRepGProp_Face props(hits.Face(i));
      gp_Pnt q;
      gp_Vec n;
      props.Normal(hits.UParameter(i), hits.VParameter(i), q, n);
      const double c = n.Dot(gp_Vec(dir));
      if (c == 0) return std::nullopt;  // tangent: this ray tells nothing
      w += c > 0 ? 1 : -1;
    }
    if (out && *out != w) return std::nullopt;
    out = w;
  }
  return out;
}

/// The union of pieces that share faces: one solid bounded by the faces used by one piece
/// only (those two pieces share are inside it); none when they do not close a shell.
std::optional<TopoDS_Shape> unionOf(const std::vector<TopoDS_Shape>& pieces) {
  BRep_Builder b;
  TopoDS_Compound all;
  b.MakeCompound(all);
  for (const TopoDS_Shape& p : pieces) b.Add(all, p);
  TopTools_IndexedDataMapOfShapeListOfShape faceSolids;
  TopExp::MapShapesAndAncestors(all, TopAbs_FACE, TopAbs_SOLID, faceSolids);
  TopoDS_Shell shell;
  b.MakeShell(shell);
  int faces = 0;
  for (const TopoDS_Shape& p : pieces)
    for (TopExp_Explorer x(p, TopAbs_FACE); x.More(); x.Next()) {
      TopTools_IndexedMapOfShape owners;
      for (const TopoDS_Shape& s : faceSolids.FindFromKey(x.Current())) owners.Add(s);
      if (owners.Extent() != 1) continue;  // between two pieces: inside the union
      b.Add(shell, x.Current());
      ++faces;
    }
  if (faces == 0) return std::nullopt;
  shell.Closed(BRep_Tool::IsClosed(shell));
  if (!shell.Closed()) return std::nullopt;
  TopoDS_Solid solid;
  b.MakeSolid(solid);
  b.Add(solid, shell);
  if (!BRepCheck_Analyzer(solid).IsValid() || !(solidVolume(solid) > 0)) return std::nullopt;
  return TopoDS_Shape(solid);
}

/// The solids with positive volume MakerVolume builds from the solid's faces (without
/// their flat shells) that lie inside the solid's material; empty when they do not account
/// for its volume, or one is not manifold and neither is their union. A solid whose faces
/// overlap itself (a wire bent so tightly that its legs interpenetrate, KiCad's 1.8 mm test
/// point) counts the overlap twice, so each piece counts its winding number times
/// (windingNumber), and pieces the faces do not wind around (air enclosed by crossing faces)
/// are not material.
/// When a piece touches itself along an edge (the legs on either side of their overlap) the
/// pieces are replaced by their union (unionOf), kept when manifold. A solid that did not
/// cross itself but touched itself along an edge lying on one of its faces (the contact
/// line of a flat strip tangent to a cylinder: KiCad's toroids and DC/DC converter pins)
/// comes back as one piece with that edge on the face: kept, non-manifold along the edge,
/// when its volume is unchanged (kImprintVolumeRel). Unimprinted, the mesher could not
/// recover the edge inside the face's triangles.
/// `history`: what became of the faces; `counted` receives the volume the solid counted
/// more than once (Σ (w − 1) V over the pieces).
std::vector<TopoDS_Shape> rebuilt(const TopoDS_Shape& solid, Handle(BRepTools_History)& history, double& counted) {
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
  double total = 0, extra = 0;
  bool manifold = true;
  for (int k = 1; k <= out.Extent(); ++k)
    if (const double v = solidVolume(out(k)); v > 0) {
      const TopoDS_Shape piece = withoutFlatShells(out(k), v);
      manifold = manifold && !nonManifold(piece);
      const std::optional<gp_Pnt> inside = pointInside(piece);
      const std::optional<int> w = inside ? windingNumber(solid, *inside) : std::nullopt;
      if (!w || *w < 0) return {};
      if (*w == 0) continue;  // enclosed by the crossing faces, outside the material
      pieces.push_back(piece);
      total += v;
      extra += (*w - 1) * v;
    }
  const double before = std::abs(solidVolume(solid));
  if (pieces.empty() || std::abs(total + extra - before) > kRebuildVolumeRel * before) return {};
  if (!manifold) {  // a piece touches itself (the legs on either side of their overlap): their union
    const std::optional<TopoDS_Shape> one = pieces.size() > 1 ? unionOf(pieces) : std::nullopt;
    if (one && !nonManifold(*one) && std::abs(solidVolume(*one) - total) <= kRebuildVolumeRel * total)
      pieces = {*one};
    else if (pieces.size() != 1 || extra != 0 || std::abs(total - before) > kImprintVolumeRel * before)
      return {};
    // else the one piece is the solid with the edges along which it touches itself now
    // shared by the faces they lie on: kept, non-manifold there
  }
  // the pieces must be as valid as the solid (KiCad battery holders: the pegs' tips meet
  // their cylinders at coincident but distinct vertices; MakerVolume dropped the tips and
  // left the cylinders' loops open by a period in (u, v), within the volume check above)
  BRep_Builder b;
  TopoDS_Compound all;
  b.MakeCompound(all);
  for (const TopoDS_Shape& p : pieces) b.Add(all, p);
  if (!BRepCheck_Analyzer(all).IsValid() && BRepCheck_Analyzer(solid).IsValid()) return {};
  counted = extra;
  return pieces;
}

}  // namespace

void rebuildSelfIntersecting(CadModel::Impl& impl, PrepareReport& report) {
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(impl.shape, TopAbs_SOLID, solids);
  std::vector<std::vector<TopoDS_Shape>> replacement(static_cast<std::size_t>(solids.Extent()) + 1);
  std::vector<Handle(BRepTools_History)> history(replacement.size());
  std::string fixed;
  const std::vector<int> crossing = selfInterferingSolids(solids);
  for (int i = 1; i <= solids.Extent(); ++i) {
    if (crossing[static_cast<std::size_t>(i)] != 1) continue;
    try {
      double counted = 0;
      replacement[static_cast<std::size_t>(i)] = rebuilt(solids(i), history[static_cast<std::size_t>(i)], counted);
      if (!replacement[static_cast<std::size_t>(i)].empty()) report.selfOverlapVolume += counted;
    } catch (const Standard_Failure&) {
      continue;  // left as it is
    }
    if (!replacement[static_cast<std::size_t>(i)].empty())
      fixed += (fixed.empty() ? "" : ", ") + std::to_string(i) + " \"" + impl.solidName(solids(i), i) + "\"";
  }
  if (fixed.empty()) return;
  replaceSolids(impl, solids, replacement, history);
  report.warnings.push_back("solid(s) " + fixed +
                            " had faces crossing or touching one another: rebuilt from their faces, split where they meet");
}

}  // namespace aniso::cad::detail
