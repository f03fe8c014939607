#include "mesher/control/ExtendedSource2d.h"

#include "mesher/core/Segment.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "mesher/core/Error.h"

namespace aniso {
namespace {

/// Pieces of a full circle in the dense outline polylines.
constexpr int kCirclePieces = 96;
/// Minimum number of pieces of a curve skeleton (on top of its adaptive polyline).
constexpr int kCurvePieces = 32;
/// Chord tolerance of the curve polyline (relative to the chord).
constexpr double kCurveTolerance = 1e-3;

Vec2 perp(const Vec2& t) { return Vec2(-t.y(), t.x()); }

/// Arc around c of radius r from angle a0 to a1 (radians), both ends included.
void appendArc(std::vector<Vec2>& out, const Vec2& c, double r, double a0, double a1) {
  const int n = std::max(2, static_cast<int>(std::ceil(std::abs(a1 - a0) / (2 * std::numbers::pi) * kCirclePieces)));
  for (int i = 0; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    out.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a));
  }
}

double angleOf(const Vec2& v) { return std::atan2(v.y(), v.x()); }

/// The closed outline of a piece of skeleton with tangents at its ends: offset at +r
/// forwards, cap around the end, offset at −r backwards, cap around the start.
std::vector<Vec2> offsetOutline(const std::vector<Vec2>& pts, const std::vector<Vec2>& normals, double r) {
  std::vector<Vec2> out;
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i) out.push_back(pts[i] + r * normals[i]);
  const double aEnd = angleOf(normals[n - 1]);
  appendArc(out, pts[n - 1], r, aEnd, aEnd - std::numbers::pi);
  for (std::size_t i = n; i-- > 0;) out.push_back(pts[i] - r * normals[i]);
  const double aStart = angleOf(-normals[0]);
  appendArc(out, pts[0], r, aStart, aStart - std::numbers::pi);
  return out;
}

/// Points along a polyline at equal metric spacing ≤ 1, both ends included.
void resample(const std::vector<Vec2>& poly, const MetricLength2d& len, std::vector<Vec2>& out) {
  if (poly.size() == 1) {
    out.push_back(poly[0]);
    return;
  }
  std::vector<double> piece(poly.size() - 1);
  double total = 0;
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
    piece[i] = len(0.5 * (poly[i] + poly[i + 1]), poly[i + 1] - poly[i]);
    if (!(std::isfinite(piece[i]) && piece[i] >= 0))
      throw MeshingError("extended metric source: metric length of an outline piece is not finite");
    total += piece[i];
  }
  const int n = std::max(1, static_cast<int>(std::ceil(total)));
  const double step = total / n;
  out.push_back(poly[0]);
  double before = 0;  // metric length up to the start of piece i
  std::size_t i = 0;
  for (int j = 1; j < n; ++j) {
    const double target = j * step;
    while (i + 1 < piece.size() && before + piece[i] < target) before += piece[i++];
    const double f = piece[i] > 0 ? std::clamp((target - before) / piece[i], 0.0, 1.0) : 0.0;
    out.push_back(poly[i] + f * (poly[i + 1] - poly[i]));
  }
  out.push_back(poly.back());
}

}  // namespace

ExtendedSource2d::ExtendedSource2d(double r) : r_(r) {
  if (!(std::isfinite(r) && r >= 0))
    throw InputError("extended metric source: radius " + std::to_string(r) + " must be finite and >= 0");
}

bool ExtendedSource2d::contains(const Vec2& x) const {
  return distance(x) <= r_ + 1e-12 * (1 + r_ + x.norm());
}

std::vector<Vec2> ExtendedSource2d::samplePoints(const MetricLength2d& len) const {
  std::vector<Vec2> out;
  for (const auto& poly : polylines()) resample(poly, len, out);
  return out;
}

// ---- point ----

PointSource2d::PointSource2d(const Vec2& centre, double r) : ExtendedSource2d(r), c_(centre) {
  if (!centre.allFinite()) throw InputError("point metric source: centre is not finite");
}

Box2 PointSource2d::bounds() const {
  Box2 b;
  b.add(c_ - Vec2::Constant(radius()));
  b.add(c_ + Vec2::Constant(radius()));
  return b;
}

std::vector<std::vector<Vec2>> PointSource2d::polylines() const {
  std::vector<std::vector<Vec2>> p{{c_}};
  if (radius() > 0) {
    p.emplace_back();
    appendArc(p.back(), c_, radius(), 0, 2 * std::numbers::pi);
  }
  return p;
}

// ---- segment ----

SegmentSource2d::SegmentSource2d(const Vec2& a, const Vec2& b, double r) : ExtendedSource2d(r), a_(a), b_(b) {
  if (!a.allFinite() || !b.allFinite()) throw InputError("segment metric source: an end point is not finite");
}

double SegmentSource2d::distance(const Vec2& x) const { return distanceToSegment<Vec2>(x, a_, b_); }

Box2 SegmentSource2d::bounds() const {
  Box2 b;
  for (const Vec2& p : {a_, b_}) {
    b.add(p - Vec2::Constant(radius()));
    b.add(p + Vec2::Constant(radius()));
  }
  return b;
}

std::vector<std::vector<Vec2>> SegmentSource2d::polylines() const {
  std::vector<std::vector<Vec2>> p{{a_, b_}};
  if (radius() > 0) {
    const Vec2 d = b_ - a_;
    if (d.norm() > 0) {
      const Vec2 n = perp(d.normalized());
      p.push_back(offsetOutline({a_, b_}, {n, n}, radius()));
    } else {
      p.emplace_back();
      appendArc(p.back(), a_, radius(), 0, 2 * std::numbers::pi);
    }
  }
  return p;
}

// ---- curve ----

CurveSource2d::CurveSource2d(Curve2dPtr curve, double t1, double t2, double r)
    : ExtendedSource2d(r), curve_(std::move(curve)), t1_(std::min(t1, t2)), t2_(std::max(t1, t2)) {
  if (!curve_) throw InputError("curve metric source: no curve");
  if (!std::isfinite(t1) || !std::isfinite(t2)) throw InputError("curve metric source: parameters are not finite");
  params_ = curve_->polyline(t1_, t2_, nullptr, kCurveTolerance);
  for (int i = 0; i <= kCurvePieces; ++i) params_.push_back(t1_ + (t2_ - t1_) * i / kCurvePieces);
  std::sort(params_.begin(), params_.end());
  params_.erase(std::unique(params_.begin(), params_.end()), params_.end());
  for (double t : params_) {
    points_.push_back(curve_->point(t));
    if (!points_.back().allFinite()) throw InputError("curve metric source: the curve is not finite at t = " + std::to_string(t));
  }
}

double CurveSource2d::distance(const Vec2& x) const {
  double best = 1e300;
  std::size_t nearest = 0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const double d = (points_[i] - x).norm();
    if (d < best) best = d, nearest = i;
  }
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) best = std::min(best, distanceToSegment<Vec2>(x, points_[i], points_[i + 1]));
  const double t = curve_->project(x, params_[nearest], t1_, t2_);
  return std::min(best, (curve_->point(t) - x).norm());
}

Box2 CurveSource2d::bounds() const {
  Box2 b;
  for (const Vec2& p : points_) {
    b.add(p - Vec2::Constant(radius()));
    b.add(p + Vec2::Constant(radius()));
  }
  return b;
}

std::vector<std::vector<Vec2>> CurveSource2d::polylines() const {
  std::vector<std::vector<Vec2>> p{points_};
  if (radius() == 0) return p;
  std::vector<Vec2> normals;
  std::vector<Vec2> pts;
  for (std::size_t i = 0; i < params_.size(); ++i) {
    const Vec2 d = curve_->d2(params_[i]).d1;
    if (!(d.allFinite() && d.norm() > 0)) continue;  // singular point: no offset direction
    normals.push_back(perp(d.normalized()));
    pts.push_back(points_[i]);
  }
  if (pts.empty()) {
    p.emplace_back();
    appendArc(p.back(), points_.front(), radius(), 0, 2 * std::numbers::pi);
  } else {
    p.push_back(offsetOutline(pts, normals, radius()));
  }
  return p;
}

}  // namespace aniso
