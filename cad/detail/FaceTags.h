#pragma once
// Internal: STEP face names and colours (CadModel::Impl::faceTags) through the
// preparation. A step that replaces faces (fixing, sewing, fragmenting) passes each tagged
// face's tag to the faces that replace it, as the step's own history names them; a face
// the step splits gives its tag to every piece, a face it deletes loses it. Where two
// tagged faces become one (the interface two parts share after fragmenting), one tag is
// kept: the resulting face's own when it is one of the two (unchanged), else the first in
// the old shape's TopExp::MapShapes order.
#include <BRepTools_History.hxx>
#include <TopTools_ListOfShape.hxx>

#include <functional>

#include "cad/detail/CadModelImpl.h"

namespace aniso::cad::detail {

/// The shapes a face became: itself when unchanged, its pieces, nothing when deleted.
/// Shapes of another type (a compound a fixer returns) are searched for their faces.
using FaceImages = std::function<TopTools_ListOfShape(const TopoDS_Shape& face)>;

/// Every tagged face of `before` (as located there) passes its tag to the faces of its
/// images that have none yet.
void carryFaceTags(CadModel::Impl& impl, const TopoDS_Shape& before, const FaceImages& images);

/// Drops the tags of faces no longer in impl.shape (what crosses the child process stays
/// small): called at the end of a step.
void dropStaleFaceTags(CadModel::Impl& impl);

/// The list of one shape (a FaceImages answer); empty for a null shape.
TopTools_ListOfShape imageList(const TopoDS_Shape& s);

/// The images of a face by an OCCT history (BRepTools_History: Modified, IsRemoved).
TopTools_ListOfShape historyImages(const Handle(BRepTools_History)& history, const TopoDS_Shape& face);

}  // namespace aniso::cad::detail
