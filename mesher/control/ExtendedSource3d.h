#pragma once
// Extended metric sources for volume control spaces (sec. 3.2.2, fig. 3.3): a constant
// metric M_s prescribed over
//   PointSource3d    the ball of radius r around a point,
//   SegmentSource3d  the capsule of radius r around a segment,
//   PrismSource3d    the prism over a planar polygon face, thickness T (the face swept
//                    from −T/2 to +T/2 along its normal); box() builds an axis-aligned box.
// The metric is not part of the source: CSAdaptive3d::insertExtendedSource(source, M_s).
//
//   contains(x)      whether x is in the source's domain;
//   samplePoints(M)  points of the skeleton (point, segment axis, face when T = 0) and of
//                    the outline (sphere, capsule surface, prism caps and side walls), at
//                    most one unit of M apart along the sampling directions: along a
//                    straight direction u the step is the requested length 1/|M u|; on
//                    curved outlines (sphere, capsule) the step is the smallest requested
//                    length h_1 of M.
#include <memory>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/metric/Metric.h"

namespace aniso {

class ExtendedSource3d {
 public:
  virtual ~ExtendedSource3d() = default;
  virtual bool contains(const Vec3& x) const = 0;
  virtual Box3 bounds() const = 0;
  virtual std::vector<Vec3> samplePoints(const Metric3d& m) const = 0;
  virtual std::unique_ptr<ExtendedSource3d> clone() const = 0;
};

class PointSource3d final : public ExtendedSource3d {
 public:
  /// Throws InputError for a non-finite centre or a radius not finite and ≥ 0.
  PointSource3d(const Vec3& centre, double r);
  bool contains(const Vec3& x) const override;
  Box3 bounds() const override;
  std::vector<Vec3> samplePoints(const Metric3d& m) const override;
  std::unique_ptr<ExtendedSource3d> clone() const override { return std::make_unique<PointSource3d>(*this); }

 private:
  Vec3 c_;
  double r_;
};

class SegmentSource3d final : public ExtendedSource3d {
 public:
  SegmentSource3d(const Vec3& a, const Vec3& b, double r);
  bool contains(const Vec3& x) const override;
  Box3 bounds() const override;
  std::vector<Vec3> samplePoints(const Metric3d& m) const override;
  std::unique_ptr<ExtendedSource3d> clone() const override { return std::make_unique<SegmentSource3d>(*this); }

 private:
  Vec3 a_, b_;
  double r_;
};

class PrismSource3d final : public ExtendedSource3d {
 public:
  /// A simple planar polygon (≥ 3 vertices, no repeated closing vertex, within 1e-9 of
  /// its size from its plane) and a thickness T ≥ 0. Throws InputError otherwise.
  PrismSource3d(std::vector<Vec3> polygon, double thickness);
  /// The axis-aligned box [lo, hi]: the rectangle at mid-height, T = hi.z − lo.z.
  static PrismSource3d box(const Vec3& lo, const Vec3& hi);
  bool contains(const Vec3& x) const override;
  Box3 bounds() const override;
  std::vector<Vec3> samplePoints(const Metric3d& m) const override;
  std::unique_ptr<ExtendedSource3d> clone() const override { return std::make_unique<PrismSource3d>(*this); }

 private:
  bool insidePolygon(const Vec2& q) const;
  Vec3 toWorld(const Vec2& q, double w) const { return o_ + q.x() * e1_ + q.y() * e2_ + w * n_; }

  std::vector<Vec3> poly_;
  std::vector<Vec2> local_;  ///< polygon in plane coordinates (e1, e2)
  Vec3 o_, e1_, e2_, n_;
  double t_, tol_;
};

}  // namespace aniso
