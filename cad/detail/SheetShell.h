#pragma once
// Internal: a shell of a solid that encloses no volume — a crack or a sheet stored as a
// shell of its own (an INTERNAL face's shell, or an open shell of faces stored FORWARD).
#include <TopoDS_Shape.hxx>

namespace aniso::cad::detail {

/// A shell is a zero-thickness sheet when it is open (an edge, not degenerate, bounds one of
/// its faces only) and its faces' vector area |∫n dA| is at least this fraction of their
/// area: a closed shell's vector area is zero, a void shell with a gap has one of the order
/// of the gap's area, a flat crack's equals its area.
inline constexpr double kSheetVectorArea = 0.25;

/// Relative chordal deflection of the coarse triangulation vectorAreaRatio measures on.
inline constexpr double kSheetMeshDeflection = 0.05;

/// |∫n dA| / ∫dA of the shell's faces, on a coarse OCCT triangulation of a copy (the faces
/// turned as they are in the shell); 0 when OCCT fails.
double vectorAreaRatio(const TopoDS_Shape& shell);

/// Open and a sheet by kSheetVectorArea (see above).
bool isSheetShell(const TopoDS_Shape& shell);

}  // namespace aniso::cad::detail
