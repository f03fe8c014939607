#include "mesher/sizing/FaceControlSpace.h"
#include "mesher/sizing/PointSizing.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <optional>

#include "mesher/control/CSAnalytic2d.h"
#include "mesher/core/Error.h"
#include "mesher/metric/ContourCurvatureMetric.h"
#include "mesher/metric/CurvatureSizing.h"
#include "mesher/metric/RobustCurvature.h"

namespace aniso {
namespace {

std::string faceName(int face) { return "face " + std::to_string(face + 1); }

/// The face's (u, v) rectangle, widened by a hair so that boundary points are inside.
Box2 faceBounds(const ModelFace& f, int face) {
  Box2 b = f.uvBounds;
  if (b.empty() || !(b.size().array() > 0).all() || !b.lo.allFinite() || !b.hi.allFinite())
    throw MeshingError(faceName(face) + ": nothing to mesh: the face has no extent on its surface (degenerate, zero area)");
  const Vec2 pad = 1e-9 * b.size() + Vec2::Constant(1e-12);
  b.lo -= pad;
  b.hi += pad;
  return b;
}

/// The face's extent in space and its area, from a (kFaceSamples + 1)² grid over its (u, v)
/// box (for a trimmed face the box's image: an upper bound).
struct FaceSample {
  Box3 box;
  double area = 0;
  /// area / extent: about the smaller side of the face (a fillet's developed width).
  double width() const { return area / std::max(box.diagonal(), 1e-300); }
};
constexpr int kFaceSamples = 8;

FaceSample sampleFace(const ParametricSurface& surface, const Box2& bounds) {
  FaceSample s;
  std::vector<Vec3> p((kFaceSamples + 1) * (kFaceSamples + 1));
  for (int i = 0; i <= kFaceSamples; ++i)
    for (int j = 0; j <= kFaceSamples; ++j) {
      const Vec2 uv = bounds.lo + Vec2(double(i) / kFaceSamples, double(j) / kFaceSamples).cwiseProduct(bounds.size());
      s.box.add(p[i * (kFaceSamples + 1) + j] = surface.point(uv));
    }
  for (int i = 0; i < kFaceSamples; ++i)
    for (int j = 0; j < kFaceSamples; ++j) {
      const Vec3 &a = p[i * (kFaceSamples + 1) + j], &b = p[(i + 1) * (kFaceSamples + 1) + j],
                 &c = p[(i + 1) * (kFaceSamples + 1) + j + 1], &d = p[i * (kFaceSamples + 1) + j + 1];
      const double q = 0.5 * ((b - a).cross(c - a).norm() + (c - a).cross(d - a).norm());
      if (std::isfinite(q)) s.area += q;
    }
  return s;
}

/// Contour curvature of every edge use of the face, inserted as point sources (alg. 3.2
/// step 6). Straight pieces carry no information (h_max everywhere) and are skipped.
void insertContourCurvature(CSQuadtree2d& cs, const Model& model, int face, const ParametricSurface& surface,
                            double gMin, const CurvatureSizing& sizing) {
  const double flat = 0.999 * sizing.hMax;
  for (const Loop& loop : model.faces[face].loops) {
    for (const EdgeUse& use : loop.uses) {
      const ModelEdge& e = model.edges[use.edge];
      if (e.degenerate) continue;
      const PCurve& pc = e.pcurves[use.pcurve];
      // Probe at the polyline vertices (chord deviation 1e-3), refined so that probes are
      // at most h(κ)/2 apart in space where the contour curves.
      const std::vector<double> ts = pc.curve->polyline(pc.t0, pc.t1, &surface, 1e-3);
      for (size_t i = 0; i + 1 < ts.size(); ++i) {
        const Vec3 a = surface.point(pc.curve->point(ts[i]));
        const Vec3 b = surface.point(pc.curve->point(ts[i + 1]));
        const double kappa = std::max(pc.curve->curvature(ts[i], surface), pc.curve->curvature(ts[i + 1], surface));
        const double h = sizing.length(kappa);
        const int n = std::clamp(static_cast<int>(std::ceil(2 * (b - a).norm() / h)), 1, 1000);
        for (int k = 0; k < n; ++k) {
          const double t = ts[i] + (ts[i + 1] - ts[i]) * k / n;
          const Metric2d m = contourCurvatureSizing(*pc.curve, t, surface, gMin, sizing);
          if (m.angleLengths().h1 >= flat) continue;
          cs.insertDiscreteSource(pc.curve->point(t), m);
        }
      }
    }
  }
}

/// Where on the face a source may lie: the (u, v) sub-box of the cells of a coarse grid
/// whose points lie in the source's region grown by the grid's largest step in space.
class FaceGrid {
 public:
  static constexpr int kCells = 32;
  FaceGrid(const ParametricSurface& surface, const Box2& bounds) : bounds_(bounds) {
    p_.resize((kCells + 1) * (kCells + 1));
    for (int i = 0; i <= kCells; ++i)
      for (int j = 0; j <= kCells; ++j) at(i, j) = surface.point(uv(i, j));
    for (int i = 0; i <= kCells; ++i)
      for (int j = 0; j <= kCells; ++j) {
        if (i < kCells) step_ = std::max(step_, (at(i + 1, j) - at(i, j)).norm());
        if (j < kCells) step_ = std::max(step_, (at(i, j + 1) - at(i, j)).norm());
      }
    if (!std::isfinite(step_)) step_ = 1e300;
  }
  /// The sub-box and its extent in space; nullopt when no grid point is near the region.
  std::optional<std::pair<Box2, double>> near(Box3 region) const {
    region.lo.array() -= step_;
    region.hi.array() += step_;
    int i0 = kCells + 1, i1 = -1, j0 = kCells + 1, j1 = -1;
    for (int i = 0; i <= kCells; ++i)
      for (int j = 0; j <= kCells; ++j) {
        const Vec3& x = p_[i * (kCells + 1) + j];
        if ((x.array() < region.lo.array()).any() || (x.array() > region.hi.array()).any()) continue;
        i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
      }
    if (i1 < 0) return std::nullopt;
    i0 = std::max(i0 - 1, 0), j0 = std::max(j0 - 1, 0), i1 = std::min(i1 + 1, kCells), j1 = std::min(j1 + 1, kCells);
    Box3 space;
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) space.add(p_[i * (kCells + 1) + j]);
    Box2 sub;
    sub.lo = uv(i0, j0);
    sub.hi = uv(i1, j1);
    return std::make_pair(sub, space.diagonal());
  }

 private:
  Vec2 uv(int i, int j) const {
    return bounds_.lo + Vec2(double(i) / kCells, double(j) / kCells).cwiseProduct(bounds_.size());
  }
  Vec3& at(int i, int j) { return p_[i * (kCells + 1) + j]; }
  Box2 bounds_;
  std::vector<Vec3> p_;
  double step_ = 0;
};

/// The user's 3D sizing restricted to the face (alg. 3.2 step 4). The global metric is a
/// continuous source. A local source usually covers a small part of a face, which the
/// continuous adaptation (it compares at a few points per control element) would miss: the
/// part of the face near the source (FaceGrid) is sampled on a (u, v) grid fine enough for
/// the source's size and every sample inside the source becomes a point source, which
/// refines the control space around it. Sources of other faces (SizingSource::faces) are
/// skipped.
void insertUserSizing(CSQuadtree2d& cs, const UserSizing& user, int face, const ParametricSurface& surface,
                      const Box2& bounds, double gMin, double hMax) {
  auto restricted = [&](const Vec2& uv, const Metric3d& m3) {
    const SurfaceD1 d = surface.d1(uv);
    return restrictToSurface(m3, d.pu, d.pv, surface.parameterizationTensor(uv, gMin));
  };
  if (user.global) {
    const Metric3d g = *user.global;
    cs.setContinuousSource(CSAnalytic2d(bounds, [&](const Vec2& uv) { return restricted(uv, g); }));
  }
  std::optional<FaceGrid> grid;  // made for the first source of the face
  for (const SizingSource& src : user.sources) {
    if (!src.sizesFace(face)) continue;
    const Box3 region = src.bounds();
    if (!grid) grid.emplace(surface, bounds);
    const auto near = grid->near(region);
    if (!near) continue;
    const auto& [sub, extent] = *near;
    const double h = src.metric.axes().lengths.minCoeff();
    const int n = std::clamp(static_cast<int>(std::ceil(2 * extent / h)), 8, 512);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const Vec2 uv = sub.lo + Vec2(double(i) / n, double(j) / n).cwiseProduct(sub.size());
        if (!src.contains(surface.point(uv))) continue;
        const Metric2d m = restricted(uv, src.metric);
        if (m.angleLengths().h1 < hMax) cs.insertDiscreteSource(uv, m);
      }
  }
}

}  // namespace

double parameterizationGuard(const SizingParameters& params, double modelDiagonal) {
  const double hmin = params.hminFor(modelDiagonal);
  return hmin * hmin;
}

std::unique_ptr<CSQuadtree2d> buildFaceControlSpace(const FaceSizingInput& in) {
  const Model& model = *in.model;
  const int face = in.face;
  const ModelFace& f = model.faces.at(static_cast<size_t>(face));
  const double diag = model.diagonal();
  CurvatureSizing sizing = CurvatureSizing::from(in.params, diag);
  if (in.chordDeviation >= 0) sizing.chordDeviation = in.chordDeviation;
  const double gMin = parameterizationGuard(in.params, diag);
  if (!f.surface) throw MeshingError("face " + std::to_string(face + 1) + ": the face has no usable surface");
  const Box2 bounds = faceBounds(f, face);
  // Every evaluation below uses a private clone of the surface (thread safety).
  const std::shared_ptr<ParametricSurface> surface = f.surface->clone();

  try {
    auto cs = std::make_unique<CSQuadtree2d>(bounds, in.params);
    // 1–2 (3.3.1, "setting initial control space"): discrete point sources first, so that
    // the control vertices are averaged from them (not intersected, as an update would)
    if (in.user && !in.user->points.empty()) insertFacePoints(*cs, in.user->points, *surface, bounds, gMin);
    // 3: surface curvature (or, with the curvature off, h_max everywhere).
    if (!in.params.curvature) {
      const double h = sizing.hMax;
      cs->setContinuousSource(CSAnalytic2d(bounds, [h](const Vec2&) { return Metric2d::isotropic(h); }));
    } else {
      // robust: bounded by the surface's secants and by the face's tolerance and width
      const RobustCurvatureBounds rb =
          RobustCurvatureBounds::of(f.uvBounds, sizing, f.tolerance, sampleFace(*surface, bounds).width());
      cs->setContinuousSource(CSAnalytic2d(
          bounds, [&](const Vec2& uv) { return robustCurvatureSizing(*surface, uv, gMin, sizing, rb); }));
    }
    // 4: the user's control spaces.
    if (in.analytic) cs->superpose(*in.analytic);
    if (in.user && !in.user->empty())
      insertUserSizing(*cs, in.user->bounded(sizing.hMin, sizing.hMax), face, *surface, bounds, gMin, sizing.hMax);
    // 6: contour curvature.
    if (in.params.curvature) insertContourCurvature(*cs, model, face, *surface, gMin, sizing);
    // 7, 8.
    cs->adaptToParameterization(*surface, gMin);
    cs->smoothGradation(in.params.gradation);
    return cs;
  } catch (const MeshingError& e) {
    throw MeshingError(faceName(face) + ": its element sizes cannot be computed: " + e.what());
  }
}

}  // namespace aniso
