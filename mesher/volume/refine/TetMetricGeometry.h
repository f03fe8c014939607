#pragma once
// Metric-space geometry of one tetrahedron for the refinement of sec. 5.5: the
// circumsphere of the tet mapped by a constant transformation tensor M (symmetric positive
// definite: the metric of the tet), q(K) of eq. 5.2, and the circumcentre mapped back
// (CCS placement).
#include "mesher/core/Types.h"

namespace aniso::refine3d {

/// Circumradius of the ideal tet: the regular tet with unit edges, R_I = √6 / 4.
inline constexpr double kIdealCircumradius = 0.6123724356957945;

/// The circumcentre of (a, b, c, d) relative to a, for the relative vectors u = b − a,
/// v = c − a, w = d − a. Returns false for a (numerically) flat tet.
bool circumcentreOffset(const Vec3& u, const Vec3& v, const Vec3& w, Vec3& centre);

/// q(K) = (R_I / R_K)³ with R_K the circumradius of M·K (eq. 5.2); 0 for a flat tet.
double metricSphereQuality(const Mat3& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// The circumcentre of M·K mapped back to physical space (CCS). False for a flat tet.
bool metricCircumcentre(const Mat3& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, Vec3& out);

}  // namespace aniso::refine3d
