#pragma once
// The quad figures of the run report (issue 7, thesis table A.1): the fraction of quads
// among the surface elements and the scaled Jacobian of the quads in 3D — at each corner
// the sine of the angle between its two edges, signed by the quad's mean normal (the sum
// of the corners' cross products), the minimum over the corners per quad: 1 for a
// rectangle, ≤ 0 for a folded or inverted corner. The same measure as the acceptance
// script (shared/tools/check_quad.py), which takes the absolute value.
#include "mesher/metric/QualityStats.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso::quad {

struct SurfaceQuadQuality {
  double fraction = 0;        ///< quads / (quads + triangles), 0 for an empty mesh
  QualityStats jacobian;      ///< per quad
  /// The quads with a corner on a model edge or vertex: the boundary layer of each face,
  /// whose elements the boundary postprocessing (BoundaryPostprocess.h, thesis 4.8.3) cares for.
  QualityStats boundaryJacobian;
};

/// One quad's scaled Jacobian in 3D (see above).
double scaledJacobian3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

SurfaceQuadQuality surfaceQuadQuality(const SurfaceMesh& mesh);

}  // namespace aniso::quad
