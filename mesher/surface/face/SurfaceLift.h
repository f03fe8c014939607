#pragma once
// SurfaceLift — the face mesher's view of its surface in 3D, for the fold guard.
//
// Every operator of the face mesher decides in (u, v) (exact orient2d) and in the face's
// metric. Near a singular point of the parameterization (a pole, where a u-range maps to
// one point, or a collapsed patch corner) a triangle counter-clockwise in (u, v) can be
// turned over on the surface: the metric there is the guarded first fundamental form
// (ParametricSurface::parameterizationTensor), blind to the direction that collapses.
// A turned-over triangle folds the surface mesh onto itself in 3D (SurfaceOrientation.h).
// The lift lets the operators refuse such a triangle: upright() is true when the chord
// triangle's normal (B − A) × (C − A) is within 75° of the sum of the surface normals at
// its corners, a singular corner (a pole, where pu × pv vanishes and its direction is
// rounding noise) not counting.
//
// The chord test means something only for a triangle small against the surface's
// curvature: a triangle of the coarse boundary triangulation spanning half a sphere is a
// placeholder the refinement will split, and its chord can face anywhere (splitting such a
// triangle legitimately makes sub-triangles whose chords point "against" the big one's).
// So a triangle whose corner normals differ by more than acos(kChordTestCosine) = 60° is
// not tested (upright); a triangle meshed within the curvature ratio differs by a few
// degrees, and the folds at singular points have corner normals within ~30° of each other.
//
// Lifted points are cached per vertex and recomputed when the vertex moved (the cache
// remembers the (u, v) it was computed for). One evaluation of p and its derivatives per
// vertex. Not thread-safe (one lift per face mesher run). With no surface, or an affine one
// (a plane: orientation in (u, v) is orientation on the surface), every test passes.
#include <limits>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/geometry/ParametricSurface.h"

namespace aniso::face {

/// Corner normals less aligned than this (any pair): the chord test does not apply.
inline constexpr double kChordTestCosine = 0.5;
/// Upright: the chord normal within acos(0.26) ≈ 75° of the corners' mean normal. A
/// triangle standing across its surface (three nearly collinear rim nodes, its chord
/// normal tangent to the surface) is as much a fold as one turned over.
inline constexpr double kUprightCosine = 0.26;
/// A triangle whose shortest chord is below this fraction of its longest has two corners
/// at one point of the surface (a pole: consecutive boundary nodes of a degenerate edge);
/// it has no orientation and is exempt (the assembly drops it).
inline constexpr double kCollapsedEdge = 1e-9;

struct LiftedPoint {
  Vec2 uv = Vec2::Constant(std::numeric_limits<double>::quiet_NaN());
  Vec3 p = Vec3::Zero();
  Vec3 n = Vec3::Zero();  ///< unit surface normal; zero at a singular point (a pole)
};

class SurfaceLift {
 public:
  /// An affine surface (a plane) needs no lift: the lift is then inactive.
  explicit SurfaceLift(const ParametricSurface* surface)
      : surface_(surface && !surface->affine() ? surface : nullptr) {}
  bool active() const { return surface_ != nullptr; }

  /// The surface point and normal at uv (not cached). Requires active().
  LiftedPoint lift(const Vec2& uv) const;
  /// The lifted vertex v at its current (u, v) (cached). Requires active().
  const LiftedPoint& at(const del2d::Triangulation2d& tri, del2d::VertexId v) const;

  /// Stores the lift of a new vertex computed before its insertion.
  void remember(del2d::VertexId v, const LiftedPoint& l) const;

  enum class Pose {
    Upright,   ///< tested: the chord normal within 75° of the corner normals
    Folded,    ///< tested: turned over or standing across the surface
    Untested,  ///< collapsed at a pole, or too large against the curvature (see above)
  };
  static Pose pose(const LiftedPoint& a, const LiftedPoint& b, const LiftedPoint& c);
  /// Two corners at one point (shortest chord below kCollapsedEdge of the longest).
  static bool collapsed(const LiftedPoint& a, const LiftedPoint& b, const LiftedPoint& c);
  /// pose() != Folded.
  static bool upright(const LiftedPoint& a, const LiftedPoint& b, const LiftedPoint& c) {
    return pose(a, b, c) != Pose::Folded;
  }
  /// upright() for three vertices at their current positions; true when inactive.
  bool upright(const del2d::Triangulation2d& tri, del2d::VertexId a, del2d::VertexId b, del2d::VertexId c) const;
  /// Both triangles a flip would make, (a, b, d) and (a, d, c) (del2d::flip), are upright;
  /// true when inactive.
  bool flipUpright(const del2d::Triangulation2d& tri, const del2d::FlipPlan& plan) const;
  /// Triangle t of the triangulation is upright; true when inactive.
  bool upright(const del2d::Triangulation2d& tri, del2d::TriId t) const;
  /// pose() of triangle t (Untested when inactive).
  Pose pose(const del2d::Triangulation2d& tri, del2d::TriId t) const;

 private:
  const ParametricSurface* surface_;
  mutable std::vector<LiftedPoint> cache_;
};

/// Mean ratio 4√3 A / (a² + b² + c²) of the chord triangle of three lifted points.
double chordMeanRatio(const LiftedPoint& a, const LiftedPoint& b, const LiftedPoint& c);

}  // namespace aniso::face
