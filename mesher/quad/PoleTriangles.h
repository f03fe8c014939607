#pragma once
// Pole triangles — the triangles of a face mesh with an edge on a pole of the
// parameterization (two corners on one global node, e.g. the degenerate edge v = ±π/2 of a
// sphere). They have no area in 3D and are not written (AddFaceMesh drops them), so they
// need no partner: the conversion (thesis 4.7) leaves them out. detach removes them from the
// mesh before the conversion: their other edges become boundary edges of the region (the
// front starts there, as at the pole in 3D) and their third corner a boundary vertex (it is
// a corner of pole elements, frozen anyway, QuadSmoothing.h). reattach puts them back
// unchanged (no adjacency: written out only).
#include <vector>

#include "mesher/quad/QuadMesh2d.h"

namespace aniso::quad {

/// Removes the live triangles with two corners on one node ≥ 0 and returns their corners;
/// the neighbours' links across them become kNone. The mesh stays valid (validate()).
std::vector<Corners> detachPoleTriangles(QuadMesh2d& mesh);

/// Removes live triangle e (appending its corners to `out`): its corners become boundary
/// vertices, the neighbours' links across it kNone. Shared by the set-aside operators.
void detachTriangle(QuadMesh2d& mesh, int e, std::vector<Corners>& out);

/// Appends detached triangles (of any set-aside operator) again as elements without links.
void reattachTriangles(QuadMesh2d& mesh, const std::vector<Corners>& triangles);

}  // namespace aniso::quad
