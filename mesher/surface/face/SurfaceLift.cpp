#include "mesher/surface/face/SurfaceLift.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace aniso::face {

using del2d::TriId;
using del2d::VertexId;

LiftedPoint SurfaceLift::lift(const Vec2& uv) const {
  const SurfaceD1 d = surface_->d1(uv);
  LiftedPoint l;
  l.uv = uv;
  l.p = d.p;
  // At a singular point (a pole: pu or pv vanishes) the normal is left zero: the direction
  // pu × pv has there is rounding noise, and the general fallback (a nearby regular point)
  // need not be the side the triangle lies on. pose() then uses the other corners.
  const Vec3 n = d.pu.cross(d.pv);
  constexpr double kSingular = 1e-10;
  const double scale = std::max(d.pu.squaredNorm(), d.pv.squaredNorm());
  l.n = n.norm() > kSingular * scale ? Vec3(n.normalized()) : Vec3::Zero();
  return l;
}

const LiftedPoint& SurfaceLift::at(const del2d::Triangulation2d& tri, VertexId v) const {
  if (cache_.size() <= v.index) cache_.resize(tri.numVertices() > v.index ? tri.numVertices() : v.index + 1);
  LiftedPoint& l = cache_[v.index];
  if (l.uv != tri.point(v)) l = lift(tri.point(v));  // NaN marks "never lifted"
  return l;
}

void SurfaceLift::remember(VertexId v, const LiftedPoint& l) const {
  if (cache_.size() <= v.index) cache_.resize(v.index + 1);
  cache_[v.index] = l;
}

bool SurfaceLift::collapsed(const LiftedPoint& a, const LiftedPoint& b, const LiftedPoint& c) {
  const double ab = (b.p - a.p).squaredNorm(), bc = (c.p - b.p).squaredNorm(), ca = (a.p - c.p).squaredNorm();
  return !(std::min({ab, bc, ca}) > kCollapsedEdge * kCollapsedEdge * std::max({ab, bc, ca}));
}

double chordMeanRatio(const LiftedPoint& a, const LiftedPoint& b, const LiftedPoint& c) {
  const Vec3 ab = b.p - a.p, bc = c.p - b.p, ca = a.p - c.p;
  const double sum = ab.squaredNorm() + bc.squaredNorm() + ca.squaredNorm();
  if (!(sum > 0)) return 0;
  return 2 * std::sqrt(3.0) * ab.cross(-ca).norm() / sum;  // 4√3 A, A = |ab × ac| / 2
}

SurfaceLift::Pose SurfaceLift::pose(const LiftedPoint& a, const LiftedPoint& b, const LiftedPoint& c) {
  // Corner normals (zero at singular corners): any two known ones too far apart, or none
  // known: untested.
  const Vec3* known[3];
  int k = 0;
  for (const LiftedPoint* x : {&a, &b, &c})
    if (x->n.squaredNorm() > 0) known[k++] = &x->n;
  if (k == 0) return Pose::Untested;
  for (int i = 0; i < k; ++i)
    for (int j = i + 1; j < k; ++j)
      if (known[i]->dot(*known[j]) < kChordTestCosine) return Pose::Untested;
  if (collapsed(a, b, c)) return Pose::Untested;  // at a pole
  const Vec3 chord = (b.p - a.p).cross(c.p - a.p);
  const Vec3 n = a.n + b.n + c.n;
  return chord.dot(n) > kUprightCosine * chord.norm() * n.norm() ? Pose::Upright : Pose::Folded;
}

bool SurfaceLift::upright(const del2d::Triangulation2d& tri, VertexId a, VertexId b, VertexId c) const {
  if (!active()) return true;
  return upright(at(tri, a), at(tri, b), at(tri, c));
}

bool SurfaceLift::upright(const del2d::Triangulation2d& tri, TriId t) const {
  const std::uint32_t* v = tri.triVertices(t);
  return upright(tri, VertexId(v[0]), VertexId(v[1]), VertexId(v[2]));
}

SurfaceLift::Pose SurfaceLift::pose(const del2d::Triangulation2d& tri, TriId t) const {
  if (!active()) return Pose::Untested;
  const std::uint32_t* v = tri.triVertices(t);
  return pose(at(tri, VertexId(v[0])), at(tri, VertexId(v[1])), at(tri, VertexId(v[2])));
}

bool SurfaceLift::flipUpright(const del2d::Triangulation2d& tri, const del2d::FlipPlan& plan) const {
  return upright(tri, plan.a, plan.b, plan.d) && upright(tri, plan.a, plan.d, plan.c);
}

}  // namespace aniso::face
