#pragma once
// moveToRingCentroid — the vertex move shared by the face mesher's 3D repair steps
// (UnfoldFace.h, FlatTriangles.h): a free vertex v goes to the (u, v) centroid of its ring
// when every triangle of its star stays counter-clockwise in (u, v) (exact orient2d) and
// upright on the surface (SurfaceLift.h) — and, with mustRaiseShape, when the smallest
// chord mean ratio of the star rises too. Check, then change; false (nothing moved) for a
// vertex on the border of the triangulation or a refused move. The caller keeps fixed
// vertices out.
#include <vector>

#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/surface/face/SurfaceLift.h"

namespace aniso::face {

bool moveToRingCentroid(del2d::Triangulation2d& tri, const SurfaceLift& lift, del2d::VertexId v,
                        bool mustRaiseShape, std::vector<del2d::VertexId>& ring);

}  // namespace aniso::face
