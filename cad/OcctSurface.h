#pragma once
// Internal: the thesis' ParametricSurface (sec. 6.2.1) over the surface of an OCCT face.
//
// The surface is the face's geometric surface with the face's location applied
// (BRep_Tool::Surface), in its own parameterization: the face's orientation and its trimming
// loops are not part of it (Model's ModelFace carries those). Evaluation goes through a
// GeomAdaptor_Surface, whose B-spline cache is mutable state: one OcctSurface must not be
// evaluated from two threads; clone() builds a new adaptor over the same (immutable)
// geometry for another thread.
//
// Errors: an OCCT exception during evaluation becomes a MeshingError naming the face and the
// (u,v) asked for; project() never throws.
#include <Geom_Surface.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <TopoDS_Face.hxx>

#include <memory>
#include <optional>
#include <string>

#include "mesher/geometry/ParametricSurface.h"

namespace aniso::cad {

class OcctSurface final : public ParametricSurface {
 public:
  /// Surface of `face` with its location applied. `name` names the face in error messages
  /// ("face 12"). Domain: the surface's natural bounds and periodicity; a direction in which
  /// the surface is unbounded (planes, cylinders, extrusions) takes the face's parametric
  /// bounds (BRepTools::UVBounds) widened by 10% of their extent on each side.
  /// Throws MeshingError if the face has no surface.
  OcctSurface(const TopoDS_Face& face, std::string name);

  Vec3 point(const Vec2& uv) const override;
  SurfaceD1 d1(const Vec2& uv) const override;
  SurfaceD2 d2(const Vec2& uv) const override;
  SurfaceDomain domain() const override { return domain_; }
  std::unique_ptr<ParametricSurface> clone() const override;
  /// A Geom_Plane (its parameterization is linear).
  bool affine() const override;

  /// The general damped Newton projection (start-nearest, periodic parameters unwrapped near
  /// `start`); when it stops at a point that is not a local minimum of the distance (the
  /// gradient does not vanish and no clamped domain bound explains it, or the Hessian is
  /// not positive semi-definite: a saddle or the farthest point, where the iteration
  /// cannot move), OCCT's global extrema search (GeomAPI_ProjectPointOnSurf) is tried and
  /// the nearer of the two answers is returned, unwrapped near `start`. Never throws.
  Vec2 project(const Vec3& x, const Vec2& start) const override;

  const std::string& name() const { return name_; }
  /// The geometry (location applied), for code in cad/ that needs OCCT algorithms.
  const Handle(Geom_Surface)& geometry() const { return surface_; }

 private:
  OcctSurface(const Handle(Geom_Surface)& surface, const SurfaceDomain& domain,
              std::string name);
  [[noreturn]] void fail(const char* what, const Vec2& uv, const char* occtMessage) const;
  bool isLocalMinimum(const Vec3& x, const Vec2& uv) const;
  std::optional<Vec2> globalProject(const Vec3& x, const Vec2& start) const;

  Handle(Geom_Surface) surface_;
  Handle(GeomAdaptor_Surface) adaptor_;
  SurfaceDomain domain_;
  std::string name_;
};

}  // namespace aniso::cad
