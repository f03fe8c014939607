#include <ShapeBuild_ReShape.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeFix_Shape.hxx>
#include <ShapeFix_Shell.hxx>
#include <ShapeFix_Solid.hxx>
#include <ShapeFix_Wire.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <cmath>

#include "cad/FalsePole.h"
#include "cad/detail/FaceTags.h"
#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {
namespace {

/// The fixer may change the solids' total volume by at most this fraction; beyond it the
/// shape is kept as read. Measured on KiCad battery holders (Keystone 2466, 2462, MPD
/// BC12AAPC, whose peg-tip faces of revolution repeat their rim circles as extra edges):
/// ShapeFix_Shape split the 1901 mm³ body into two 0.19 mm³ solids made of the peg tips
/// alone; on ../shared/assemblies and ../shared/models the fixer changes no total by more
/// than 1e-5.
constexpr double kFixVolumeRel = 1e-3;

double solidsVolume(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  double v = 0;
  for (int i = 1; i <= solids.Extent(); ++i) v += std::abs(solidVolume(solids(i)));
  return v;
}

}  // namespace

void fixShape(CadModel::Impl& impl, double diag, PrepareReport& report) {
  try {
    const InternalFaces internal = collectInternalFaces(impl.shape);
    // Wires::None: ShapeFix_Wire is left out (the volume fallback below); NoDegenerated: its
    // edges are not turned into degenerated ones (the false-pole fallback)
    enum class Wires { All, NoDegenerated, None };
    const auto runFixer = [&impl, diag](Wires wires, int& split) {
      Handle(ShapeFix_Shape) f = new ShapeFix_Shape(impl.shape);
      f->SetMaxTolerance(1e-3 * diag);  // fixes may not open gaps larger than a small fraction of the model
      if (wires == Wires::None) f->FixSolidTool()->FixShellTool()->FixFaceTool()->FixWireMode() = 0;
      if (wires == Wires::NoDegenerated) f->FixSolidTool()->FixShellTool()->FixFaceTool()->FixWireTool()->FixDegeneratedMode() = 0;
      split = splitLoopsOfClosedEdges(impl.shape, *f->Context());
      f->Perform();
      return f;
    };
    int split = 0;
    Handle(ShapeFix_Shape) fixer = runFixer(Wires::All, split);
    // A rim circle lying within its vertex's tolerance (inflated by the STEP translation's
    // false poles) is turned into a degenerated edge by the wire fixing: a face whose rims
    // are then all false poles covers its surface several times over (KiCad's CHK EI48
    // transformer: the pins' fillets of revolution, 4π and 6π wide, meshed folded). Fixed
    // again without that repair when it made such faces.
    // (the shape as read is counted only when the fixed one has such faces: the common case
    // costs one pass over the faces)
    const int fixedCount = fixer->Shape().IsNull() ? 0 : facesBoundedByFalsePoles(fixer->Shape());
    if (const int asRead = fixedCount > 0 ? facesBoundedByFalsePoles(impl.shape) : 0; fixedCount > asRead) {
      int again = 0;
      Handle(ShapeFix_Shape) other = runFixer(Wires::NoDegenerated, again);
      if (!other->Shape().IsNull() && facesBoundedByFalsePoles(other->Shape()) <= asRead) {
        fixer = other;
        split = again;
        report.warnings.push_back("shape fixing left the rim circles that lie within their vertices' tolerance as "
                                  "they are (turning them into poles would have folded their faces)");
      }
    }
    if (split > 0)
      report.warnings.push_back(std::to_string(split) +
                                " face(s) had a boundary loop made of separate closed edges (no seam joining "
                                "them): split into one loop per edge");
    const double volumeBefore = solidsVolume(impl.shape);
    const auto changesVolume = [volumeBefore](double v) { return std::abs(v - volumeBefore) > kFixVolumeRel * volumeBefore; };
    if (const double fixedVolume = fixer->Shape().IsNull() ? volumeBefore : solidsVolume(fixer->Shape());
        changesVolume(fixedVolume)) {
      const std::string changed = "from " + num(volumeBefore) + " to " + num(fixedVolume);
      fixer = runFixer(Wires::None, split);
      if (fixer->Shape().IsNull() || changesVolume(solidsVolume(fixer->Shape()))) {
        report.warnings.push_back("shape fixing would change the solids' volume " + changed + "; the shape is kept as read");
        rebuildSelfIntersecting(impl, report);
        imprintSelfContacts(impl, report);
        return;
      }
      report.warnings.push_back("shape fixing left the faces' boundary loops as read (repairing them would change the "
                                "solids' volume " + changed + ")");
    }
    const TopoDS_Shape fixed = fixer->Shape();
    if (fixed.IsNull()) {
      report.warnings.push_back("shape fixing produced nothing; the shape is kept as read");
      return;
    }
    // Carry the part names over to the fixed solids.
    TopTools_IndexedMapOfShape solids;
    TopExp::MapShapes(impl.shape, TopAbs_SOLID, solids);
    for (int i = 1; i <= solids.Extent(); ++i) {
      const TopoDS_Shape key = solids(i).Located(TopLoc_Location());
      if (!impl.nameIndex.IsBound(key)) continue;
      const int name = impl.nameIndex.Find(key);
      TopTools_IndexedMapOfShape images;
      TopExp::MapShapes(fixer->Context()->Value(solids(i)), TopAbs_SOLID, images);
      for (int k = 1; k <= images.Extent(); ++k) {
        const TopoDS_Shape ik = images(k).Located(TopLoc_Location());
        if (!impl.nameIndex.IsBound(ik)) impl.nameIndex.Bind(ik, name);
      }
    }
    // A solid the fixer rebuilt without recording it at the solid level (only its faces
    // are in the context) keeps its place: with as many solids as before, the i-th fixed
    // solid still unnamed takes the i-th original's name.
    TopTools_IndexedMapOfShape fixedSolids;
    TopExp::MapShapes(fixed, TopAbs_SOLID, fixedSolids);
    if (fixedSolids.Extent() == solids.Extent())
      for (int i = 1; i <= solids.Extent(); ++i) {
        const TopoDS_Shape key = solids(i).Located(TopLoc_Location());
        const TopoDS_Shape fk = fixedSolids(i).Located(TopLoc_Location());
        if (impl.nameIndex.IsBound(key) && !impl.nameIndex.IsBound(fk)) impl.nameIndex.Bind(fk, impl.nameIndex.Find(key));
      }
    const TopoDS_Shape before = impl.shape;
    impl.shape = fixed;
    restoreInternalFaces(impl, internal, fixer->Context());
    const Handle(ShapeBuild_ReShape) context = fixer->Context();
    carryFaceTags(impl, before, [&context](const TopoDS_Shape& f) { return imageList(context->Apply(f)); });
    dropStaleFaceTags(impl);
    rebuildSelfIntersecting(impl, report);
    imprintSelfContacts(impl, report);
  } catch (const Standard_Failure& e) {
    report.warnings.push_back(std::string("shape fixing failed (") + e.GetMessageString() +
                              "); the shape is kept as read");
  }
}

}  // namespace aniso::cad::detail
