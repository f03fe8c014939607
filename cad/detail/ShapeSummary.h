#pragma once
// Internal: counts and measures of an OCCT shape.
#include <TopoDS_Shape.hxx>

#include "cad/detail/CadModelImpl.h"

namespace aniso::cad::detail {

ShapeSummary summarize(const CadModel::Impl& impl);

/// Bounding box of the shape from its geometry (no triangulation); B-splines bounded by
/// their poles, so it may be slightly larger than the exact box.
Box3 exactBoundingBox(const TopoDS_Shape& shape);

}  // namespace aniso::cad::detail
