#pragma once
// The user's sizing in model coordinates (read from --sizing FILE.json by io/SizingFile):
// a global metric and extended metric sources (thesis sec. 3.2.2, fig. 3.3). Inside a
// source's region the mesh metric is intersected with the source's metric, so a source
// can only make elements smaller.
#include <optional>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/metric/Metric.h"

namespace aniso {

struct SizingSource {
  enum class Kind { Point, Segment, Box } kind = Kind::Point;
  Vec3 a = Vec3::Zero();  ///< point, segment start, box min
  Vec3 b = Vec3::Zero();  ///< segment end, box max
  double radius = 0;      ///< ball / capsule radius (point, segment)
  Metric3d metric;
  /// The model faces (0-based, sorted) the source sizes; empty: every face and solid
  /// meeting its region. A source with faces leaves the other faces in its region, and the
  /// volume, alone (the proximity loop's: the faces of the thin part, not of every part in
  /// its box).
  std::vector<int> faces;

  /// Does the source size model face f?
  bool sizesFace(int f) const;

  /// Is x inside the region of the source (ball, capsule, box)?
  bool contains(const Vec3& x) const;
  /// The box around the region: every x that contains() accepts lies in it.
  Box3 bounds() const;
};

/// A discrete point source (thesis 3.3.1, "Introducing discrete data"): the metric wanted at
/// a point, e.g. the adapted metric at a node of a solver's mesh (the adapt command). A face
/// takes the points near it (mesher/sizing/PointSizing.h), a solid those in its box.
struct SizingPoint {
  Vec3 at = Vec3::Zero();
  Metric3d metric;
};

struct UserSizing {
  std::optional<Metric3d> global;
  std::vector<SizingSource> sources;
  std::vector<SizingPoint> points;

  bool empty() const { return !global && sources.empty() && points.empty(); }
  /// The intersection of the global metric and of every source containing x (points are
  /// not regions, face sources not everywhere: both left out); nothing when none applies.
  std::optional<Metric3d> metricAt(const Vec3& x) const;
  /// The same sizing with every length of every metric bounded to [hmin, hmax] (directions
  /// kept): h_min and h_max are hard bounds every source respects. 0 < hmin ≤ hmax.
  UserSizing bounded(double hmin, double hmax) const;
};

/// The 2D sizing component M_s (acting on S^R, see mesher/metric/SurfaceMetric.h) that a 3D
/// metric M3 induces on a surface at a point with first derivatives J = [pu pv] and
/// parameterization tensor M_p: lengths measured in the tangent plane agree,
/// |M_s M_p y| = |M3 J y| for every parametric vector y, i.e.
/// M_s² = M_p⁻¹ Jᵀ M3² J M_p⁻¹.
/// The tensor gets kRestrictedTensorFloor times its trace added on its diagonal: a nearly
/// singular J (a 3D box source over a face with a degenerate parametrisation;
/// docs/measurements.md) made the small eigenvalue round to ≤ 0 and the face's
/// control space throw; the floor bounds the anisotropy of the restricted metric to 1e5.
inline constexpr double kRestrictedTensorFloor = 1e-10;
Metric2d restrictToSurface(const Metric3d& m3, const Vec3& pu, const Vec3& pv, const Mat2& mp);

}  // namespace aniso
