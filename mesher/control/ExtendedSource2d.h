#pragma once
// Extended metric sources for surface / planar control spaces (sec. 3.2.2, fig. 3.2):
// a constant metric M_s prescribed over the neighbourhood of radius r ≥ 0 of
//   PointSource2d    a point P                     (P, M_s, r),
//   SegmentSource2d  a segment P1P2                (P1, P2, M_s, r),
//   CurveSource2d    a parametric curve c(t), t ∈ [t1, t2]   (c(t), t1, t2, M_s, r).
// Coordinates and r are in the control space's own coordinates (the parametric plane
// (u, v) of a surface control space; model units for planar domains). The metric itself is
// not part of the source: CSAdaptive2d::insertExtendedSource(source, M_s) takes it.
//
// A source supplies what the general-level ACS procedure needs:
//   contains(x)       whether x is in the source's domain (distance to the skeleton ≤ r);
//   samplePoints(len) points of the skeleton (the point, segment or curve itself) and of
//                     the outline (circle, or the offset curves at ±r with semicircular
//                     end caps), consecutive points of each at most one unit apart
//                     according to len(at, v), the metric length of vector v at point at.
// Not thread-safe (a curve source evaluates its curve): use one source per thread.
#include <functional>
#include <memory>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/geometry/ParametricCurve2d.h"

namespace aniso {

/// Metric length of vector v at point at (e.g. |M_s M_p(at) v|).
using MetricLength2d = std::function<double(const Vec2& at, const Vec2& v)>;

class ExtendedSource2d {
 public:
  virtual ~ExtendedSource2d() = default;
  double radius() const { return r_; }
  /// Euclidean distance from x to the skeleton.
  virtual double distance(const Vec2& x) const = 0;
  /// distance(x) ≤ r (with a round-off tolerance of 1e-12 (1 + r + |x|)).
  bool contains(const Vec2& x) const;
  /// Bounding box of the domain (skeleton widened by r).
  virtual Box2 bounds() const = 0;
  /// Skeleton and outline points at most one metric unit apart (see the file comment).
  /// Throws MeshingError when len returns a non-finite or negative value.
  std::vector<Vec2> samplePoints(const MetricLength2d& len) const;
  virtual std::unique_ptr<ExtendedSource2d> clone() const = 0;

 protected:
  /// Throws InputError unless r is finite and ≥ 0.
  explicit ExtendedSource2d(double r);
  /// Dense polylines (straight pieces between points) of the skeleton and the outline;
  /// a polyline of one point is a single sample.
  virtual std::vector<std::vector<Vec2>> polylines() const = 0;

 private:
  double r_;
};

class PointSource2d final : public ExtendedSource2d {
 public:
  PointSource2d(const Vec2& centre, double r);
  double distance(const Vec2& x) const override { return (x - c_).norm(); }
  Box2 bounds() const override;
  std::unique_ptr<ExtendedSource2d> clone() const override { return std::make_unique<PointSource2d>(*this); }

 protected:
  std::vector<std::vector<Vec2>> polylines() const override;

 private:
  Vec2 c_;
};

class SegmentSource2d final : public ExtendedSource2d {
 public:
  SegmentSource2d(const Vec2& a, const Vec2& b, double r);
  double distance(const Vec2& x) const override;
  Box2 bounds() const override;
  std::unique_ptr<ExtendedSource2d> clone() const override { return std::make_unique<SegmentSource2d>(*this); }

 protected:
  std::vector<std::vector<Vec2>> polylines() const override;

 private:
  Vec2 a_, b_;
};

class CurveSource2d final : public ExtendedSource2d {
 public:
  /// The piece [t1, t2] (any order) of the curve. Throws InputError for a null curve or
  /// non-finite parameters.
  CurveSource2d(Curve2dPtr curve, double t1, double t2, double r);
  double distance(const Vec2& x) const override;
  Box2 bounds() const override;
  std::unique_ptr<ExtendedSource2d> clone() const override { return std::make_unique<CurveSource2d>(*this); }

 protected:
  std::vector<std::vector<Vec2>> polylines() const override;

 private:
  Curve2dPtr curve_;
  double t1_, t2_;
  std::vector<double> params_;  ///< dense parameters along the piece
  std::vector<Vec2> points_;    ///< curve points at params_
};

}  // namespace aniso
