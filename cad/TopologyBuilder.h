#pragma once
// Internal: builds the mesher's Model (mesher/model/Model.h) from an OCCT shape.
// Ids follow TopExp::MapShapes order of the whole shape, 1-based. The orientation and seam
// conventions are those of mesher/model/Model.h, detailed at the top of TopologyBuilder.cpp.
#include <TopoDS_Shape.hxx>

#include <functional>
#include <string>

#include "mesher/model/Model.h"

namespace aniso::cad {

/// `solidName(solid, id)` names each solid (see CadModel::Impl::solidName); `solidVolume`
/// gives ModelSolid::cadVolume (detail::accurateVolume when empty).
/// Throws MeshingError naming the face when a face has no usable pcurve or surface.
Model buildTopology(const TopoDS_Shape& shape,
                    const std::function<std::string(const TopoDS_Shape&, int)>& solidName,
                    const std::function<double(const TopoDS_Shape&)>& solidVolume = {});

}  // namespace aniso::cad
