#pragma once
// Discrete point sources (UserSizing::points, thesis 3.3.1) into the control spaces:
//   a face: every point within kPointOnFaceFraction of its smallest size from the face's
//   surface (a node of the solver's mesh on this face, or just under it) is projected
//   (ParametricSurface::project, started at the nearest of a kPointSampleGrid² sample of
//   the face's parametric box) and, when its (u, v) lies in the box, inserted as a discrete
//   source with its metric restricted to the surface (restrictToSurface); sources not
//   finer than hMax are left out (the face's own sizing already holds them).
//   a solid: every point in the box of the volume control space, its metric f =
//   kVolumeLengthFactor times finer: a point gives the tetrahedra's size (the mesh the solver
//   gets), while the volume convention makes tets f times longer than the sources' size.
// Updating an initialized control space (3.3.1, "updating control space") refines it
// around each point and intersects the metric there.
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
                      const Box2& bounds, double gMin, double hMax);

/// `lengthFactor`: the volume's tet-to-source length factor (kVolumeLengthFactor).
void insertSolidPoints(CSAdaptive3d& cs, const std::vector<SizingPoint>& points, const Box3& box, double lengthFactor);

}  // namespace aniso
