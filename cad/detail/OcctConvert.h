#pragma once
// Internal: OCCT values as anisomesh ones — points and vectors as Eigen vectors, and the
// text of an OCCT exception for the MeshingError that replaces it (its message, or its
// type name when the message is empty).
#include <Standard_Failure.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>
#include <gp_Vec2d.hxx>

#include <string>

#include "mesher/core/Types.h"

namespace aniso::cad::detail {

std::string occtMessage(const Standard_Failure& e);

inline Vec2 toEigen(const gp_Pnt2d& p) { return {p.X(), p.Y()}; }
inline Vec2 toEigen(const gp_Vec2d& v) { return {v.X(), v.Y()}; }
inline Vec3 toEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
inline Vec3 toEigen(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

}  // namespace aniso::cad::detail
