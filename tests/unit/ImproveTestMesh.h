#pragma once
// Test fixtures of the face-improvement tests (improve_*_test.cpp): face triangulations
// built with the del2d kernel (boundary loop inserted and constrained, interior points
// inserted with a constant metric, the enlarged box removed by domain marking), metrics
// and quality helpers.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/delaunay/DomainMarking.h"
#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/delaunay/Validate2d.h"
#include "mesher/metric/MeanRatio.h"

namespace improve_test {

using namespace aniso;
using namespace aniso::del2d;

/// A control space from a callable uv → (M_s, M_p).
class FunctionCS final : public ControlSpace2d {
 public:
  using Fn = std::function<SurfaceMetricAt(const Vec2&)>;
  FunctionCS(Box2 bounds, Fn f) : bounds_(bounds), f_(std::move(f)) {}
  SurfaceMetricAt getMetric(const Vec2& uv) const override { return f_(uv); }
  Box2 bounds() const override { return bounds_; }

 private:
  Box2 bounds_;
  Fn f_;
};

inline Box2 box(double x0, double y0, double x1, double y1) {
  Box2 b;
  b.add(Vec2(x0, y0));
  b.add(Vec2(x1, y1));
  return b;
}

/// Constant sizing metric: h1 along angle alpha, h2 across; M_p = mp.
inline FunctionCS constantCS(double alpha, double h1, double h2, const Mat2& mp = Mat2::Identity()) {
  const Metric2d m = Metric2d::fromAngle(alpha, h1, h2);
  return FunctionCS(box(0, 0, 1, 1), [m, mp](const Vec2&) { return SurfaceMetricAt{m, mp}; });
}

struct TestFace {
  Triangulation2d tri;
  std::vector<std::uint8_t> fixed;
  std::vector<VertexId> boundary;  ///< the loop, domain on the left
};

/// Boundary loop (domain on the left) with `perEdge` segments per polygon edge, interior
/// points inserted with the transformation m; everything outside removed.
inline TestFace buildFace(const std::vector<Vec2>& polygon, int perEdge, const std::vector<Vec2>& interior,
                          const Mat2& m) {
  Box2 bounds;
  for (const Vec2& p : polygon) bounds.add(p);
  Triangulation2dOptions topt;
  topt.transform = m;
  TestFace f{Triangulation2d(bounds, topt), {}, {}};
  for (std::size_t e = 0; e < polygon.size(); ++e) {
    const Vec2 a = polygon[e], b = polygon[(e + 1) % polygon.size()];
    for (int k = 0; k < perEdge; ++k) {
      const InsertResult r = insertPoint(f.tri, a + (b - a) * (double(k) / perEdge), m);
      EXPECT_EQ(r.status, InsertStatus::Inserted);
      f.boundary.push_back(r.vertex);
    }
  }
  std::vector<std::pair<VertexId, VertexId>> contour;
  for (std::size_t k = 0; k < f.boundary.size(); ++k)
    contour.emplace_back(f.boundary[k], f.boundary[(k + 1) % f.boundary.size()]);
  for (const auto& [a, b] : contour) EXPECT_TRUE(f.tri.setConstrainedEdge(a, b));
  for (const Vec2& p : interior) insertPoint(f.tri, p, m);  // points on the contour are refused
  const DomainMarks marks = markDomain(f.tri, contour);
  EXPECT_EQ(marks.missingEdges, 0u);
  EXPECT_EQ(marks.conflicts, 0u);
  std::vector<std::uint8_t> remove(f.tri.triangleSlots(), 0);
  for (std::size_t k = 0; k < remove.size(); ++k)
    remove[k] = f.tri.isAlive(TriId(static_cast<std::uint32_t>(k))) && !marks.inside[k];
  removeTriangles(f.tri, remove);
  f.fixed.assign(f.tri.numVertices(), 0);
  for (VertexId v : f.boundary) f.fixed[v.index] = 1;
  for (VertexId c : f.tri.corners()) f.fixed[c.index] = 1;
  return f;
}

inline std::vector<Vec2> unitSquare() { return {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}; }

/// Uniform random points in [0,1]² (uniform in any constant metric space as well).
inline std::vector<Vec2> randomPoints(int n, std::uint64_t seed, double lo = 0.0, double hi = 1.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<Vec2> pts;
  for (int k = 0; k < n; ++k) {
    const double x = u(rng);
    pts.emplace_back(x, u(rng));
  }
  return pts;
}

/// The transformation of a constant control space (M = M_s M_p).
inline Mat2 transformOf(const ControlSpace2d& cs) { return cs.getMetric(Vec2(0.5, 0.5)).transformation(); }

/// Mean and minimum η_M over the live triangles with the constant transformation m.
struct EtaSummary {
  double mean = 0, min = 1;
  std::size_t count = 0;
};
inline EtaSummary etaSummary(const Triangulation2d& tri, const Mat2& m) {
  EtaSummary s;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!tri.isAlive(t)) continue;
    const double e = meanRatio(m, tri.point(tri.vertex(t, 0)), tri.point(tri.vertex(t, 1)), tri.point(tri.vertex(t, 2)));
    s.mean += e, s.min = std::min(s.min, e), ++s.count;
  }
  if (s.count > 0) s.mean /= static_cast<double>(s.count);
  return s;
}

inline std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

#define EXPECT_TRI_VALID(tri)                                           \
  do {                                                                  \
    const auto problems_ = ::aniso::del2d::validate(tri);               \
    EXPECT_TRUE(problems_.empty()) << ::improve_test::joined(problems_); \
  } while (0)

/// The constrained edges as sorted vertex pairs.
inline std::vector<std::pair<std::uint32_t, std::uint32_t>> constrainedEdges(const Triangulation2d& tri) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> e;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!tri.isAlive(t)) continue;
    for (int i = 0; i < 3; ++i)
      if (tri.isConstrained(t, i)) {
        const std::uint32_t a = tri.vertex(t, kNext[i]).index, b = tri.vertex(t, kPrev[i]).index;
        e.emplace_back(std::min(a, b), std::max(a, b));
      }
  }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

/// Coordinates of every vertex (bitwise comparison of runs).
inline std::vector<Vec2> allPoints(const Triangulation2d& tri) {
  std::vector<Vec2> p;
  for (std::uint32_t v = 0; v < tri.numVertices(); ++v) p.push_back(tri.point(VertexId(v)));
  return p;
}

/// Vertex triples of the live triangles, slot by slot.
inline std::vector<std::uint32_t> allTriangles(const Triangulation2d& tri) {
  std::vector<std::uint32_t> t;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    if (!tri.isAlive(TriId(k))) continue;
    for (int i = 0; i < 3; ++i) t.push_back(tri.vertex(TriId(k), i).index);
  }
  return t;
}

/// Number of boundary segments per unit square side for unit metric edges along it.
inline int segmentsAlong(const Mat2& m, const Vec2& side) {
  return std::max(2, static_cast<int>(std::lround((m * side).norm())));
}

/// Random interior points for a unit-metric mesh of the unit square: as many points as
/// unit equilateral triangles need (area_M / (√3/2)).
inline std::vector<Vec2> unitMeshPoints(const Mat2& m, std::uint64_t seed) {
  const double areaM = std::abs(m.determinant());
  return randomPoints(static_cast<int>(areaM / (std::sqrt(3.0) / 2)), seed);
}

/// The unit square meshed for the constant transformation m: boundary spacing ≈ 1 in
/// metric, random interior points, Delaunay for the transformation `delaunay`.
inline TestFace squareFace(const Mat2& m, std::uint64_t seed, const Mat2& delaunay) {
  const int nx = segmentsAlong(m, Vec2(1, 0)), ny = segmentsAlong(m, Vec2(0, 1));
  // Square with nx segments along u and ny along v (polygon edges split evenly per side).
  std::vector<Vec2> poly;
  for (int k = 0; k < nx; ++k) poly.emplace_back(double(k) / nx, 0);
  for (int k = 0; k < ny; ++k) poly.emplace_back(1, double(k) / ny);
  for (int k = 0; k < nx; ++k) poly.emplace_back(1 - double(k) / nx, 1);
  for (int k = 0; k < ny; ++k) poly.emplace_back(0, 1 - double(k) / ny);
  return buildFace(poly, 1, unitMeshPoints(m, seed), delaunay);
}
/// Same, Delaunay in the metric itself.
inline TestFace squareFace(const Mat2& m, std::uint64_t seed) { return squareFace(m, seed, m); }

}  // namespace improve_test
