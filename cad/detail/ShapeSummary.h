#pragma once
// Internal: counts and measures of an OCCT shape.
#include <TopoDS_Shape.hxx>

#include "cad/detail/CadModelImpl.h"

namespace aniso::cad::detail {

/// The solids' volumes (accurateVolume) and the shape's counts and areas.
ShapeSummary summarize(const CadModel::Impl& impl);

/// The volume of a solid by OCCT's adaptive integral (relative error at most 1e-5), or by
/// its fixed-order integral when the two agree within that; 0 when OCCT fails. The
/// fixed-order integral OCCT gives by default can be far off on B-spline solids (by a third
/// on a helical thread: docs/measurements.md).
double accurateVolume(const TopoDS_Shape& solid);

/// accurateVolume of a solid of impl's shape, remembered in impl.volumes (per part: every
/// placement of one TShape shares it).
double solidVolumeOf(const CadModel::Impl& impl, const TopoDS_Shape& solid);

/// Bounding box of the shape from its geometry (no triangulation); B-splines bounded by
/// their poles, so it may be slightly larger than the exact box.
Box3 exactBoundingBox(const TopoDS_Shape& shape);

}  // namespace aniso::cad::detail
