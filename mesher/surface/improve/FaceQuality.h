#pragma once
// FaceQuality — the quality coefficients of sec. 2.5 for one face triangulation in its
// parametric plane, with the face's control space (the report's quality block):
//   eta  η_M per live triangle (MeanRatio.h, eq. 2.47–2.48), M = M_s M_p taken at the
//        centroid;
//   mu   μ_M per unique edge (MetricLength.h, eq. 2.49), M taken at the midpoint (eq. 2.14);
//   ek   E_K per live triangle (NonConformity.h, eq. 2.50–2.51): the sizing at the centroid
//        against the simplex metric of the triangle mapped to S^R with M_p at the centroid.
// E_K does not exist for a (numerically) degenerate triangle: such triangles are counted in
// `degenerate` and left out of ek (they stay in eta, with η_M ≈ 0).
// One control-space call per triangle and per edge; no state, thread-safe for const input.
#include <array>
#include <cstddef>
#include <span>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/metric/QualityStats.h"

namespace aniso {

struct FaceQuality {
  QualityStats eta, mu, ek;
  std::size_t degenerate = 0;  ///< triangles left out of ek
};

/// Over the live triangles of tri.
FaceQuality faceQuality(const del2d::Triangulation2d& tri, const ControlSpace2d& cs);

/// Over a triangle list (vertex indices into uv, e.g. a FaceMesh); an edge shared by
/// several triangles counts once. Throws MeshingError for an index out of range.
FaceQuality faceQuality(std::span<const Vec2> uv, std::span<const std::array<int, 3>> triangles,
                        const ControlSpace2d& cs);

}  // namespace aniso
