#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRep_Builder.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS_Compound.hxx>

#include <set>

#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {
namespace {

/// The solids an argument became in the general fuse (itself when untouched).
TopTools_IndexedMapOfShape imagesOf(BRepAlgoAPI_BuilderAlgo& gf, const TopoDS_Shape& solid) {
  TopTools_IndexedMapOfShape out;
  if (gf.IsDeleted(solid)) return out;
  const TopTools_ListOfShape& mod = gf.Modified(solid);
  if (mod.IsEmpty()) {
    out.Add(solid);
  } else {
    for (const TopoDS_Shape& s : mod) TopExp::MapShapes(s, TopAbs_SOLID, out);
  }
  return out;
}

}  // namespace

void fragmentSolids(CadModel::Impl& impl, double diag, PrepareReport& report) {
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(impl.shape, TopAbs_SOLID, solids);
  if (solids.Extent() < 2) return;
  try {
    BRepAlgoAPI_BuilderAlgo gf;
    TopTools_ListOfShape args;
    for (int i = 1; i <= solids.Extent(); ++i) args.Append(solids(i));
    gf.SetArguments(args);
    gf.SetRunParallel(false);  // determinism
    gf.SetNonDestructive(true);
    // Touching parts of an assembly rarely touch exactly: glue within a tiny fraction.
    gf.SetFuzzyValue(1e-7 * diag);
    gf.Build();
    if (gf.HasErrors() || !gf.IsDone()) {
      report.warnings.push_back("fragmenting the solids failed; solids are meshed independently");
      return;
    }
    // Which argument solids produced each result solid: two means they overlap.
    TopTools_DataMapOfShapeInteger owner;
    std::set<std::pair<int, int>> overlaps;
    std::vector<TopTools_IndexedMapOfShape> images(solids.Extent() + 1);
    for (int i = 1; i <= solids.Extent(); ++i) {
      images[i] = imagesOf(gf, solids(i));
      for (int k = 1; k <= images[i].Extent(); ++k) {
        const TopoDS_Shape& im = images[i](k);
        if (owner.IsBound(im)) overlaps.insert({owner.Find(im), i});
        else owner.Bind(im, i);
      }
    }
    if (!overlaps.empty()) {
      for (const auto& p : overlaps) report.overlappingSolids.push_back(p);
      report.warnings.push_back(std::to_string(overlaps.size()) +
                                " pair(s) of solids overlap; the solids are not fragmented");
      return;
    }
    // New shape: the fragmented solids, in argument order, plus whatever was not a solid.
    BRep_Builder b;
    TopoDS_Compound c;
    b.MakeCompound(c);
    for (int i = 1; i <= solids.Extent(); ++i) {
      const TopoDS_Shape key = solids(i).Located(TopLoc_Location());
      const bool named = impl.nameIndex.IsBound(key);
      const int name = named ? impl.nameIndex.Find(key) : -1;
      for (int k = 1; k <= images[i].Extent(); ++k) {
        b.Add(c, images[i](k));
        const TopoDS_Shape ik = images[i](k).Located(TopLoc_Location());
        if (named && !impl.nameIndex.IsBound(ik)) impl.nameIndex.Bind(ik, name);
      }
    }
    TopTools_IndexedMapOfShape inSolid;
    for (int i = 1; i <= solids.Extent(); ++i) TopExp::MapShapes(solids(i), TopAbs_FACE, inSolid);
    TopTools_IndexedMapOfShape allFaces;
    TopExp::MapShapes(impl.shape, TopAbs_FACE, allFaces);
    for (int i = 1; i <= allFaces.Extent(); ++i)
      if (!inSolid.Contains(allFaces(i))) b.Add(c, allFaces(i));
    impl.shape = c;
    // Interfaces: faces bounding two solids.
    TopTools_IndexedDataMapOfShapeListOfShape faceSolids;
    TopExp::MapShapesAndAncestors(c, TopAbs_FACE, TopAbs_SOLID, faceSolids);
    int shared = 0;
    for (int i = 1; i <= faceSolids.Extent(); ++i) {
      TopTools_IndexedMapOfShape distinct;
      for (const TopoDS_Shape& s : faceSolids(i)) distinct.Add(s);
      if (distinct.Extent() >= 2) ++shared;
    }
    report.sharedFaces = shared;
  } catch (const Standard_Failure& e) {
    report.warnings.push_back(std::string("fragmenting the solids failed (") + e.GetMessageString() +
                              "); solids are meshed independently");
  }
}

}  // namespace aniso::cad::detail
