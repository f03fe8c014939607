#pragma once
// Discrete point sources (UserSizing::points, thesis 3.3.1) into the control spaces:
//   a face: every point within kPointOnFaceFraction of its smallest size from the face's
//   surface (a node of the solver's mesh on this face, or just under it) is projected
//   (ParametricSurface::project, started at the nearest of a kPointSampleGrid² sample of
//   the face's parametric box) and, when its (u, v) lies in the box, inserted as a discrete
//   source with its metric restricted to the surface (restrictToSurface). Call it on a
//   fresh control space, before the continuous sources: the control vertices are then
//   the inverse-distance average of the points near them (3.3.1, "setting initial control
//   space"), not their intersection (the update procedure), which at a curved front makes
//   neighbouring anisotropic points of different directions isotropic and fine.
//   a solid: every point in the box of the volume control space. As every size, a point's
//   size is that of the surface triangles and f = kVolumeLengthFactor times shorter than
//   the tetrahedra's inside (VolumeControlSpace.h): who wants tets of its size (the adapt
//   command) gives a metric f times finer.
#include <vector>

#include "mesher/control/CSAdaptive2d.h"
#include "mesher/control/CSAdaptive3d.h"
#include "mesher/sizing/UserSizing.h"

namespace aniso {

/// A point further than this fraction of its smallest size from the surface is not on the face.
inline constexpr double kPointOnFaceFraction = 0.25;
/// Samples per parametric direction for the projections' start points.
inline constexpr int kPointSampleGrid = 24;

void insertFacePoints(CSAdaptive2d& cs, const std::vector<SizingPoint>& points, const ParametricSurface& surface,
                      const Box2& bounds, double gMin);

void insertSolidPoints(CSAdaptive3d& cs, const std::vector<SizingPoint>& points, const Box3& box);

}  // namespace aniso
