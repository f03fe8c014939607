#include "mesher/control/ExtendedSource3d.h"

#include "mesher/core/Segment.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "mesher/core/Error.h"

namespace aniso {
namespace {

/// Refuse outlines that would need more sample points than this (h tiny for the source).
constexpr double kMaxSamplePoints = 2e7;

void checkRadius(double r, const char* what) {
  if (!(std::isfinite(r) && r >= 0))
    throw InputError(std::string(what) + ": radius " + std::to_string(r) + " must be finite and >= 0");
}

/// Number of pieces of a length measured in units of the requested size, checked.
int pieces(double metricLength) {
  if (!std::isfinite(metricLength) || metricLength > kMaxSamplePoints)
    throw MeshingError("extended metric source: the outline would need " + std::to_string(metricLength) +
                       " sample points per line; the requested size is too small for the source");
  return std::max(1, static_cast<int>(std::ceil(metricLength)));
}

void reserveChecked(std::vector<Vec3>& out, double count) {
  if (!(count <= kMaxSamplePoints))
    throw MeshingError("extended metric source: the outline would need about " + std::to_string(count) +
                       " sample points; the requested size is too small for the source");
  out.reserve(out.size() + static_cast<std::size_t>(count));
}

/// Orthonormal u, w with (u, w, t) right-handed for a unit t.
void completeFrame(const Vec3& t, Vec3& u, Vec3& w) {
  const Vec3 helper = std::abs(t.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  u = t.cross(helper).normalized();
  w = t.cross(u);
}

/// Rings of the sphere (c, r) around axis t between polar angles th0 and th1, spacing ≤ h.
void appendSphereZone(std::vector<Vec3>& out, const Vec3& c, double r, const Vec3& t, double th0, double th1,
                      double h) {
  Vec3 u, w;
  completeFrame(t, u, w);
  const int nth = pieces(r * std::abs(th1 - th0) / h);
  reserveChecked(out, (nth + 1.0) * (2 * std::numbers::pi * r / h + 1));
  for (int i = 0; i <= nth; ++i) {
    const double th = th0 + (th1 - th0) * i / nth;
    const double rho = r * std::sin(th);
    const Vec3 centre = c + r * std::cos(th) * t;
    if (rho <= 1e-12 * r) {
      out.push_back(centre);
      continue;
    }
    const int nph = pieces(2 * std::numbers::pi * rho / h);
    for (int j = 0; j < nph; ++j) {
      const double ph = 2 * std::numbers::pi * j / nph;
      out.push_back(centre + rho * (std::cos(ph) * u + std::sin(ph) * w));
    }
  }
}

double smallestLength(const Metric3d& m) { return m.axes().lengths(0); }

double tolerance(const Box3& b) { return 1e-12 * (1 + b.diagonal()); }

}  // namespace

// ---- point ----

PointSource3d::PointSource3d(const Vec3& centre, double r) : c_(centre), r_(r) {
  checkRadius(r, "point metric source");
  if (!centre.allFinite()) throw InputError("point metric source: centre is not finite");
}

bool PointSource3d::contains(const Vec3& x) const { return (x - c_).norm() <= r_ + tolerance(bounds()); }

Box3 PointSource3d::bounds() const {
  Box3 b;
  b.add(c_ - Vec3::Constant(r_));
  b.add(c_ + Vec3::Constant(r_));
  return b;
}

std::vector<Vec3> PointSource3d::samplePoints(const Metric3d& m) const {
  std::vector<Vec3> out{c_};
  if (r_ > 0) appendSphereZone(out, c_, r_, Vec3::UnitZ(), 0, std::numbers::pi, smallestLength(m));
  return out;
}

// ---- segment ----

SegmentSource3d::SegmentSource3d(const Vec3& a, const Vec3& b, double r) : a_(a), b_(b), r_(r) {
  checkRadius(r, "segment metric source");
  if (!a.allFinite() || !b.allFinite()) throw InputError("segment metric source: an end point is not finite");
}

bool SegmentSource3d::contains(const Vec3& x) const {
  return distanceToSegment<Vec3>(x, a_, b_) <= r_ + tolerance(bounds());
}

Box3 SegmentSource3d::bounds() const {
  Box3 b;
  for (const Vec3& p : {a_, b_}) {
    b.add(p - Vec3::Constant(r_));
    b.add(p + Vec3::Constant(r_));
  }
  return b;
}

std::vector<Vec3> SegmentSource3d::samplePoints(const Metric3d& m) const {
  std::vector<Vec3> out;
  const Vec3 d = b_ - a_;
  const double h = smallestLength(m);
  if (!(d.norm() > 0)) {
    out.push_back(a_);
    if (r_ > 0) appendSphereZone(out, a_, r_, Vec3::UnitZ(), 0, std::numbers::pi, h);
    return out;
  }
  const Vec3 t = d.normalized();
  Vec3 u, w;
  completeFrame(t, u, w);
  const int n = pieces(m.length(d));
  const int nph = r_ > 0 ? pieces(2 * std::numbers::pi * r_ / h) : 0;
  reserveChecked(out, (n + 1.0) * (nph + 1));
  for (int i = 0; i <= n; ++i) {
    const Vec3 p = a_ + (double(i) / n) * d;
    out.push_back(p);
    for (int j = 0; j < nph; ++j) {
      const double ph = 2 * std::numbers::pi * j / nph;
      out.push_back(p + r_ * (std::cos(ph) * u + std::sin(ph) * w));
    }
  }
  if (r_ > 0) {
    appendSphereZone(out, b_, r_, t, 0, 0.5 * std::numbers::pi, h);
    appendSphereZone(out, a_, r_, -t, 0, 0.5 * std::numbers::pi, h);
  }
  return out;
}

// ---- prism ----

PrismSource3d::PrismSource3d(std::vector<Vec3> polygon, double thickness) : poly_(std::move(polygon)), t_(thickness) {
  if (!(std::isfinite(thickness) && thickness >= 0))
    throw InputError("prism metric source: thickness " + std::to_string(thickness) + " must be finite and >= 0");
  if (poly_.size() < 3) throw InputError("prism metric source: the face needs at least 3 vertices");
  Vec3 centre = Vec3::Zero();
  Box3 box;
  for (const Vec3& p : poly_) {
    if (!p.allFinite()) throw InputError("prism metric source: a face vertex is not finite");
    centre += p / double(poly_.size());
    box.add(p);
  }
  Vec3 normal = Vec3::Zero();  // Newell
  for (std::size_t i = 0; i < poly_.size(); ++i)
    normal += (poly_[i] - centre).cross(poly_[(i + 1) % poly_.size()] - centre);
  const double size = box.diagonal();
  if (!(normal.norm() > 1e-12 * size * size)) throw InputError("prism metric source: the face has no area");
  n_ = normal.normalized();
  o_ = centre;
  e1_ = (poly_[1] - poly_[0]) - (poly_[1] - poly_[0]).dot(n_) * n_;
  if (!(e1_.norm() > 0)) e1_ = n_.unitOrthogonal();
  e1_.normalize();
  e2_ = n_.cross(e1_);
  for (const Vec3& p : poly_) {
    if (std::abs((p - o_).dot(n_)) > 1e-9 * size) throw InputError("prism metric source: the face is not planar");
    local_.emplace_back((p - o_).dot(e1_), (p - o_).dot(e2_));
  }
  tol_ = tolerance(bounds());
}

PrismSource3d PrismSource3d::box(const Vec3& lo, const Vec3& hi) {
  const double z = 0.5 * (lo.z() + hi.z());
  return PrismSource3d({Vec3(lo.x(), lo.y(), z), Vec3(hi.x(), lo.y(), z), Vec3(hi.x(), hi.y(), z), Vec3(lo.x(), hi.y(), z)},
                       hi.z() - lo.z());
}

bool PrismSource3d::insidePolygon(const Vec2& q) const {
  bool in = false;
  const std::size_t n = local_.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2& a = local_[i];
    const Vec2& b = local_[j];
    // Within the tolerance of an edge counts as inside.
    const Vec2 d = b - a;
    const double f = std::clamp((q - a).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
    if ((q - (a + f * d)).norm() <= tol_) return true;
    if ((a.y() > q.y()) != (b.y() > q.y()) && q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
      in = !in;
  }
  return in;
}

bool PrismSource3d::contains(const Vec3& x) const {
  const Vec3 r = x - o_;
  if (std::abs(r.dot(n_)) > 0.5 * t_ + tol_) return false;
  return insidePolygon(Vec2(r.dot(e1_), r.dot(e2_)));
}

Box3 PrismSource3d::bounds() const {
  Box3 b;
  for (const Vec3& p : poly_) {
    b.add(p - 0.5 * t_ * n_);
    b.add(p + 0.5 * t_ * n_);
  }
  return b;
}

std::vector<Vec3> PrismSource3d::samplePoints(const Metric3d& m) const {
  std::vector<Vec3> out;
  const int nw = t_ > 0 ? pieces(m.length(t_ * n_)) : 0;
  // Side walls: the polygon boundary on every layer across the thickness.
  for (int j = 0; j <= nw; ++j) {
    const double w = nw ? -0.5 * t_ + t_ * j / nw : 0.0;
    for (std::size_t i = 0; i < poly_.size(); ++i) {
      const std::size_t k = (i + 1) % poly_.size();
      const int ne = pieces(m.length(poly_[k] - poly_[i]));
      reserveChecked(out, ne);
      for (int s = 0; s < ne; ++s) out.push_back(toWorld(local_[i] + (double(s) / ne) * (local_[k] - local_[i]), w));
    }
  }
  // Caps (or the face itself when T = 0): grid at the requested lengths along e1, e2.
  Box2 lb;
  for (const Vec2& q : local_) lb.add(q);
  const Vec2 ext = lb.size();
  const int n1 = pieces(m.length(ext.x() * e1_)), n2 = pieces(m.length(ext.y() * e2_));
  reserveChecked(out, (n1 + 1.0) * (n2 + 1) * (nw ? 2 : 1));
  for (const double w : nw ? std::vector<double>{-0.5 * t_, 0.5 * t_} : std::vector<double>{0.0})
    for (int i = 0; i <= n1; ++i)
      for (int j = 0; j <= n2; ++j) {
        const Vec2 q(lb.lo.x() + ext.x() * i / n1, lb.lo.y() + ext.y() * j / n2);
        if (insidePolygon(q)) out.push_back(toWorld(q, w));
      }
  return out;
}

}  // namespace aniso
