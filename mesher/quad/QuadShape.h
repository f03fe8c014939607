#pragma once
// Shape measures and legality checks of the quad conversion, in the face's metric
// (thesis 2.2, 4.7–4.8). The metric of a vertex is S = (MᵀM)^{1/2} of the control space's
// transformation M = M_s M_p (|S x| = |M x| for every x, VertexMetricCache.h); the metric
// of an element is the mean of its corners' S.
//
//   scaledJacobian(S, p)  min over the 4 corners of sin of the corner angle in metric
//                         space: 1 for a square (rectangle) in metric, ≤ 0 at a reflex or
//                         flat corner. The measure the acceptance checks use in 3D.
//   triangleShape(S, …)   the mean ratio η = 4√3 A / Σ l² in metric (1 equilateral).
//   convexCCW(mesh, c)    every corner strictly counter-clockwise, by exact orient2d: the
//                         legality test of every operator that creates an element.
#include <array>
#include <span>
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/geometry/ParametricSurface.h"
#include "mesher/quad/QuadMesh2d.h"

namespace aniso::quad {

/// S for every vertex of a QuadMesh2d, evaluated on demand (vertices added by the
/// operators get theirs when first asked). A vertex whose M is not finite or singular
/// takes the identity scaled to the mean size of the usable ones. With a surface, also the
/// vertex's 3D point, so that quads are judged in 3D too (near poles and on strongly
/// curved parameterizations the metric, linear around each vertex, misjudges them).
class VertexMetrics {
 public:
  /// `nodes`: the SurfaceMesh's node positions, used for the vertices on the face boundary
  /// (node ≥ 0) — the edge discretization's points, which the surface at the pcurve's
  /// (u, v) matches only to the CAD tolerance (enough to flip a flat boundary corner).
  VertexMetrics(const QuadMesh2d& mesh, const ControlSpace2d& cs, const ParametricSurface* surface = nullptr,
                std::span<const Vec3> nodes = {});
  const Mat2& at(int v);
  /// Re-evaluates v's 3D point after v moved (its metric stays cached for the pass).
  void refreshPoint(int v) {
    if (surface_ && v < static_cast<int>(xyz_.size())) xyz_[v] = pointOf(v);
  }
  /// The 3D point of v (nullptr without a surface).
  const Vec3* point(int v);
  /// Forget v's metric (the vertex moved or its index is reused); re-evaluated when asked.
  void invalidate(int v) {
    if (v < static_cast<int>(known_.size())) known_[v] = 0;
  }
  /// Mean of the corners' S (3 or 4 corners; c[3] == kNone for a triangle).
  Mat2 element(const Corners& c);
  /// Metric length of the edge (a, b), with the mean of the endpoints' S.
  double length(int a, int b);
  /// The ratio ≥ 1 of the metric lengths of edge (a, b) measured with S_a and with S_b:
  /// the local metric gradation along the edge (a_5 of eq. 4.4).
  double gradation(int a, int b);
  const ControlSpace2d& space() const { return cs_; }

 private:
  void evaluate(int v);
  Vec3 pointOf(int v) const;
  const QuadMesh2d& mesh_;
  const ControlSpace2d& cs_;
  const ParametricSurface* surface_;
  std::span<const Vec3> nodes_;
  std::vector<Mat2> s_;
  std::vector<Vec3> xyz_;
  std::vector<std::uint8_t> known_;
  Mat2 fallback_ = Mat2::Identity();
};

double scaledJacobian(const Mat2& s, const std::array<Vec2, 4>& p);
double triangleShape(const Mat2& s, const Vec2& a, const Vec2& b, const Vec2& c);

/// Exact: every corner of the element (3 or 4 corners) turns strictly counter-clockwise.
bool convexCCW(const QuadMesh2d& mesh, const Corners& c);

/// The quality of a would-be element: for a quad the scaled Jacobian, in 3D when there is a
/// surface (QuadQuality.h; pole quads, triangles in 3D, in metric), else in metric;
/// triangleShape in metric for a triangle; −1 when convexCCW fails.
double elementQuality(const QuadMesh2d& mesh, VertexMetrics& metrics, const Corners& c);

/// Every live element convexCCW; one message per offending element.
std::vector<std::string> validateGeometry(const QuadMesh2d& mesh);

}  // namespace aniso::quad
