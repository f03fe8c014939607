#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include "cad/detail/FaceTags.h"
#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {

void replaceSolids(CadModel::Impl& impl, const TopTools_IndexedMapOfShape& solids,
                   const std::vector<std::vector<TopoDS_Shape>>& replacement,
                   const std::vector<Handle(BRepTools_History)>& history) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  const auto replaced = [&](int i) {
    return static_cast<std::size_t>(i) < replacement.size() && !replacement[static_cast<std::size_t>(i)].empty();
  };
  for (int i = 1; i <= solids.Extent(); ++i) {
    if (!replaced(i)) {
      b.Add(c, solids(i));
      continue;
    }
    const TopoDS_Shape key = solids(i).Located(TopLoc_Location());
    for (const TopoDS_Shape& p : replacement[static_cast<std::size_t>(i)]) {
      b.Add(c, p);
      if (impl.nameIndex.IsBound(key)) impl.nameIndex.Bind(p.Located(TopLoc_Location()), impl.nameIndex.Find(key));
    }
  }
  addLooseFaces(impl.shape, solids, c);
  impl.shape = c;
  for (int i = 1; i <= solids.Extent(); ++i)
    if (replaced(i))
      carryFaceTags(impl, solids(i), [&h = history[static_cast<std::size_t>(i)]](const TopoDS_Shape& f) {
        return historyImages(h, f);
      });
  dropStaleFaceTags(impl);
}

}  // namespace aniso::cad::detail
