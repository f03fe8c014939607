#pragma once
// False poles: degenerated edges (one 3D point) whose pcurve crosses a part of the surface
// that is not that point. OpenCASCADE's STEP translation bridges (u, v) jumps of a periodic
// face with such edges, and its shape fixing may turn a real rim circle lying within an
// inflated vertex tolerance into one.
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

namespace aniso::cad {

/// True for a degenerated edge of `face` (FORWARD) whose pcurve maps, at five points, to
/// surface points farther from the edge's vertex than kFalsePoleTolFactor times the edge's
/// tolerance and kFalsePoleRel of the face's size. (Not the vertex's tolerance: the
/// translation grows it to cover the bridge, up to the size of the face itself;
/// docs/measurements.md.)
bool falsePole(const TopoDS_Edge& edge, const TopoDS_Face& face);

/// Faces of `shape` with a wire made of degenerated edges and seams only, one of them a
/// false pole: a face whose rims are all false poles, which the mesher cannot bound (its
/// loop spans several periods and covers the surface more than once).
int facesBoundedByFalsePoles(const TopoDS_Shape& shape);

}  // namespace aniso::cad
