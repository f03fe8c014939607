#pragma once
// Internal: what OcctCurve2d (a pcurve) and OcctCurve3d (an edge's 3D curve) share.
//   OcctCurveRange          the edge's parameter range [first, last] and the curve's natural
//                           range extended to cover it (cover());
//   loadOcctCurve(n, k, f)  runs f (the loading of a curve and its adaptor); an OCCT
//                           exception becomes MeshingError "<n>: OCCT could not load the
//                           <k>: <message>" (other exceptions pass);
//   occtCurvePoint / occtCurveD2   evaluate an OCCT adaptor (Geom2dAdaptor_Curve with
//                           gp_Pnt2d / gp_Vec2d, Adaptor3d_Curve with gp_Pnt / gp_Vec) at t
//                           into Eigen vectors; an OCCT exception becomes MeshingError "<n>:
//                           OCCT failed to evaluate the <k>'s point|derivatives at t = <t>:
//                           <message>" (t with 17 digits).
#include <string>

#include "cad/detail/OcctConvert.h"
#include "mesher/core/Error.h"

namespace aniso::cad::detail {

struct OcctCurveRange {
  double first = 0, last = 0;  ///< the edge's parameter range (as stored, any order)
  double tMin = 0, tMax = 0;   ///< the curve's natural range covering [first, last]
  /// Sets tMin / tMax from the natural range [natFirst, natLast] widened to the edge's
  /// range; an infinite end (lines) is the edge's end.
  void cover(double natFirst, double natLast);
};

template <class Load>
void loadOcctCurve(const std::string& name, const char* kind, Load&& load) {
  try {
    load();
  } catch (const Standard_Failure& e) {
    throw MeshingError(name + ": OCCT could not load the " + kind + ": " + occtMessage(e));
  }
}

[[noreturn]] void failOcctCurve(const std::string& name, const char* kind, const char* what, double t,
                                const std::string& message);

template <class Pnt, class Adaptor>
auto occtCurvePoint(const Adaptor& adaptor, double t, const std::string& name, const char* kind) {
  Pnt p;
  try {
    adaptor.D0(t, p);
  } catch (const Standard_Failure& e) {
    failOcctCurve(name, kind, "point", t, occtMessage(e));
  }
  return toEigen(p);
}

/// D2: Curve2dD2 / Curve3dD2 ({p, d1, d2}).
template <class D2, class Pnt, class Vector, class Adaptor>
D2 occtCurveD2(const Adaptor& adaptor, double t, const std::string& name, const char* kind) {
  Pnt p;
  Vector v1, v2;
  try {
    adaptor.D2(t, p, v1, v2);
  } catch (const Standard_Failure& e) {
    failOcctCurve(name, kind, "derivatives", t, occtMessage(e));
  }
  return {toEigen(p), toEigen(v1), toEigen(v2)};
}

}  // namespace aniso::cad::detail
