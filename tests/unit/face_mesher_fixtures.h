#pragma once
// Shared helpers of the face mesher tests: FaceBoundary generators (nodes along polygon
// sides at a given spacing, or at unit metric length in a control space — a simple
// stand-in for the contour discretization of alg. 4.1), control spaces (constant isotropic,
// AN1 of appendix A.1) and mesh measures (area, η_M with M at the centroid, μ_M with M at
// the edge midpoint).
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mesher/control/CSAnalytic2d.h"
#include "mesher/metric/MeanRatio.h"
#include "mesher/metric/QualityStats.h"
#include "mesher/surface/FaceBoundary.h"

namespace facetest {

using aniso::Box2;
using aniso::FaceBoundary;
using aniso::FaceMesh;
using aniso::Mat2;
using aniso::Vec2;

using Polygon = std::vector<Vec2>;

inline std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

inline double signedArea(const Polygon& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& x = p[i];
    const Vec2& y = p[(i + 1) % p.size()];
    a += x.x() * y.y() - x.y() * y.x();
  }
  return 0.5 * a;
}

/// Regular polygon approximating a circle; clockwise when `hole`.
inline Polygon circle(const Vec2& c, double r, int n, bool hole) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n * (hole ? -1 : 1);
    p.emplace_back(c.x() + r * std::cos(t), c.y() + r * std::sin(t));
  }
  return p;
}

inline Polygon rectangle(double x0, double y0, double x1, double y1) {
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

/// Nodes along every side of every polygon: ceil(length / spacing) equal segments per side
/// (spacing ≤ 0: the polygon's corners only). Global nodes numbered from `firstNode`.
inline FaceBoundary polygonBoundary(const std::vector<Polygon>& loops, double spacing, int face = 0,
                                    int firstNode = 0) {
  FaceBoundary b;
  b.face = face;
  int node = firstNode;
  for (const Polygon& poly : loops) {
    std::vector<aniso::BoundaryNode> loop;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2& x = poly[i];
      const Vec2& y = poly[(i + 1) % poly.size()];
      const int n = spacing > 0 ? std::max(1, static_cast<int>(std::ceil((y - x).norm() / spacing - 1e-9))) : 1;
      for (int k = 0; k < n; ++k) loop.push_back({x + (y - x) * (static_cast<double>(k) / n), node++});
    }
    b.loops.push_back(std::move(loop));
  }
  return b;
}

/// Nodes along every side at (about) unit metric length in cs: the side's metric length
/// is integrated with the metric at the midpoints of `samples` pieces, the side gets
/// max(1, round(L)) segments of equal metric length.
inline FaceBoundary metricBoundary(const std::vector<Polygon>& loops, const aniso::ControlSpace2d& cs,
                                   int samples = 4000) {
  FaceBoundary b;
  int node = 0;
  for (const Polygon& poly : loops) {
    std::vector<aniso::BoundaryNode> loop;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2& x = poly[i];
      const Vec2& y = poly[(i + 1) % poly.size()];
      std::vector<double> cum(samples + 1, 0.0);
      for (int s = 0; s < samples; ++s) {
        const Vec2 a = x + (y - x) * (static_cast<double>(s) / samples);
        const Vec2 c = x + (y - x) * (static_cast<double>(s + 1) / samples);
        cum[s + 1] = cum[s] + (cs.getMetric(0.5 * (a + c)).transformation() * (c - a)).norm();
      }
      const int n = std::max(1, static_cast<int>(std::lround(cum.back())));
      loop.push_back({x, node++});
      for (int k = 1; k < n; ++k) {
        const double target = cum.back() * k / n;
        const auto it = std::lower_bound(cum.begin(), cum.end(), target);
        const int s = std::max(1, static_cast<int>(it - cum.begin()));
        const double f = (target - cum[s - 1]) / (cum[s] - cum[s - 1]);
        loop.push_back({x + (y - x) * ((s - 1 + f) / samples), node++});
      }
    }
    b.loops.push_back(std::move(loop));
  }
  return b;
}

inline std::shared_ptr<aniso::CSAnalytic2d> isotropicSpace(const Box2& box, double h) {
  const aniso::Metric2d m = aniso::Metric2d::isotropic(h);
  return std::make_shared<aniso::CSAnalytic2d>(box, [m](const Vec2&) { return m; });
}

/// AN1 (appendix A.1) on [0, 2] × [0, 1]: α = π/6, h1 = 0.01 k, h2 = k (0.0101 − 0.005 u).
inline std::shared_ptr<aniso::CSAnalytic2d> an1Space(double k) {
  Box2 box;
  box.add(Vec2(0, 0));
  box.add(Vec2(2, 1));
  return std::make_shared<aniso::CSAnalytic2d>(box, [k](const Vec2& uv) {
    return aniso::Metric2d::fromAngle(std::numbers::pi / 6, 0.01 * k, k * (0.0101 - 0.005 * uv.x()));
  });
}

inline double meshArea(const FaceMesh& m) {
  double a = 0;
  for (const auto& t : m.triangles) {
    const Vec2 e1 = m.uv[t[1]] - m.uv[t[0]], e2 = m.uv[t[2]] - m.uv[t[0]];
    a += 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
  }
  return a;
}

/// η_M per triangle (M at the centroid).
inline aniso::QualityStats meanRatioStats(const FaceMesh& m, const aniso::ControlSpace2d& cs) {
  aniso::QualityStats s;
  for (const auto& t : m.triangles) {
    const Vec2 &a = m.uv[t[0]], &b = m.uv[t[1]], &c = m.uv[t[2]];
    s.add(aniso::meanRatio(cs.getMetric((a + b + c) / 3.0).transformation(), a, b, c));
  }
  return s;
}

/// The undirected edges of the mesh, each once.
inline std::vector<std::pair<int, int>> meshEdges(const FaceMesh& m) {
  std::vector<std::pair<int, int>> e;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) e.emplace_back(std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3]));
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

/// μ_M per edge (M at the midpoint); `inRange` counts the edges in [lo, hi].
inline aniso::QualityStats edgeLengthStats(const FaceMesh& m, const aniso::ControlSpace2d& cs, double lo = 0.6,
                                           double hi = 1.5, std::size_t* inRange = nullptr) {
  aniso::QualityStats s;
  std::size_t in = 0;
  for (const auto& [i, j] : meshEdges(m)) {
    const Vec2 &a = m.uv[i], &b = m.uv[j];
    const double l = (cs.getMetric(0.5 * (a + b)).transformation() * (b - a)).norm();
    s.add(l);
    in += l >= lo && l <= hi;
  }
  if (inRange != nullptr) *inRange = in;
  return s;
}

inline bool pointInPolygon(const Vec2& p, const Polygon& poly) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[i], &b = poly[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

}  // namespace facetest
