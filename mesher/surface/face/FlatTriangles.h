#pragma once
// removeFlatTriangles — a postprocessing of the worst elements in 3D (thesis 4.6.4 measures
// them in the face's metric): triangles whose chord triangle is nearly degenerate on the
// surface (mean ratio below kFlatMeanRatio: a cap with an angle near 180° or a needle).
//
// The face metric M = M_s M_p takes the parameterization tensor at one point of a
// triangle; near a singular point of the parameterization (the tip of a surface of
// revolution, a collapsed patch corner) M_p changes by orders of magnitude across one
// triangle and a triangle that is fine in that metric can be a flat cap on the surface (its
// three corners nearly collinear in 3D). Such caps make the volume's boundary slivers.
// The threshold is far below what an anisotropic mesh asks for (a triangle stretched 10:1
// has mean ratio ≈ 0.17), so intended stretching is left alone.
//
// For each flat triangle, in index order: flip an unconstrained edge when the pair's
// smaller 3D mean ratio rises and both new triangles are counter-clockwise in (u, v) and
// upright (SurfaceLift.h); else move a free corner (not fixed, not on the border) to the
// (u, v) centroid of its ring when its star stays valid and upright and its smallest 3D
// mean ratio rises. At most maxRounds rounds, stopping when one changes nothing. Never
// touches constrained edges or fixed vertices. Inactive lift: nothing to do.
#include <cstdint>
#include <vector>

#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/surface/face/SurfaceLift.h"

namespace aniso::face {

inline constexpr double kFlatMeanRatio = 0.05;

struct FlatTriangleStats {
  int before = 0, after = 0, flips = 0, moves = 0;
};

FlatTriangleStats removeFlatTriangles(del2d::Triangulation2d& tri, const SurfaceLift& lift,
                                      const std::vector<std::uint8_t>& fixed, int maxRounds = 4);

}  // namespace aniso::face
