#include "mesher/volume/VolumeControlSpace.h"

#include "mesher/sizing/PointSizing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>
#include <vector>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/control/CSOctree3d.h"
#include "mesher/control/ExtendedSource3d.h"
#include "mesher/core/Error.h"
#include "mesher/metric/AnisotropyLimit.h"
#include "mesher/metric/IsotropicTensor.h"
#include "mesher/metric/MetricInterpolation.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/metric/SimplexMetric.h"
#include "mesher/volume/BoundaryMesh.h"

namespace aniso {
namespace {

/// lengthFactorFrom: a point beyond L h_v / f_max (1 − this) of the surface has f_max (where
/// L h_v / f_max equals the near radius up to rounding, as for M_v = M / f_max everywhere
/// inside a uniform solid, its factor is f_max to this relative accuracy).
constexpr double kFactorSlack = 1e-9;

/// The key of no point (NaN bits): an empty slot of VolumeMetricSpace's boundary table.
constexpr std::array<std::uint64_t, 3> kEmpty = {~std::uint64_t{0}, ~std::uint64_t{0}, ~std::uint64_t{0}};

/// Relative triangle area (of the squared longest edge) below which a boundary triangle
/// gives no metric (a sliver triangle's simplex metric is meaningless).
constexpr double kFlatTriangle = 1e-8;

std::vector<char> solidFaces(const Model& model, int solid) {
  std::vector<char> in(model.faces.size(), 0);
  const ModelSolid& s = model.solids.at(static_cast<std::size_t>(solid));
  auto addShell = [&](int shell) {
    if (shell < 0) return;
    for (const FaceUse& u : model.shells.at(static_cast<std::size_t>(shell)).faces)
      if (u.face >= 0 && static_cast<std::size_t>(u.face) < in.size()) in[u.face] = 1;
  };
  addShell(s.outerShell);
  for (const int v : s.voidShells) addShell(v);
  for (const EmbeddedFace& e : s.embedded)
    if (e.face >= 0 && static_cast<std::size_t>(e.face) < in.size()) in[e.face] = 1;
  return in;
}

/// Eq. 3.3: the surface metric of triangle (a, b, c) extended to 3D (see the header).
bool triangleMetric(const Vec3& a, const Vec3& b, const Vec3& c, double gammaA, double hmin, Metric3d& out) {
  const Vec3 ab = b - a, ac = c - a;
  const Vec3 n = ab.cross(ac);
  const double longest = std::max({ab.squaredNorm(), ac.squaredNorm(), (c - b).squaredNorm()});
  if (!(n.norm() > kFlatTriangle * longest)) return false;
  const Vec3 u = ab.normalized(), nn = n.normalized(), w = nn.cross(u);
  const Vec2 pa(0, 0), pb(ab.dot(u), ab.dot(w)), pc(ac.dot(u), ac.dot(w));
  const MetricAxes<2> ax = Metric2d::fromTensor(simplexMetricTensor(pa, pb, pc)).axes();
  const double h1 = std::max(ax.lengths(0), hmin), h2 = std::max(ax.lengths(1), hmin);
  const double h3 = std::max(std::min(h1, h2), std::max(h1, h2) / gammaA);
  const Vec3 e1 = ax.directions(0, 0) * u + ax.directions(1, 0) * w;
  const Vec3 e2 = ax.directions(0, 1) * u + ax.directions(1, 1) * w;
  out = limitAnisotropy(Metric3d::fromDirections(e1, e2, nn, h1, h2, h3), gammaA);
  return true;
}

std::unique_ptr<ExtendedSource3d> extendedSource(const SizingSource& src) {
  switch (src.kind) {
    case SizingSource::Kind::Point:
      return std::make_unique<PointSource3d>(src.a, src.radius);
    case SizingSource::Kind::Segment:
      return std::make_unique<SegmentSource3d>(src.a, src.b, src.radius);
    case SizingSource::Kind::Box:
      return std::make_unique<PrismSource3d>(PrismSource3d::box(src.a, src.b));
  }
  return nullptr;
}

bool overlaps(const Box3& a, const Box3& b) {
  return !a.empty() && !b.empty() && (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

}  // namespace

double volumeGradation(double gamma, double factor) {
  if (!(gamma > 1) || !(factor > 0)) return gamma;
  const double slope = 2 * (gamma - 1) / (gamma + 1) / factor;  // eq. 2.27's a_max, in M_v
  return (2 + slope) / (2 - slope);
}

VolumeMetricSpace::VolumeMetricSpace(std::shared_ptr<const ControlSpace3d> user, std::span<const Vec3> boundary,
                                     double factor, std::shared_ptr<const TriangleTree> surface)
    : user_(std::move(user)), factor_(factor), surface_(std::move(surface)) {
  if (!user_) throw MeshingError("VolumeMetricSpace: no control space");
  if (!(factor > 0) || !std::isfinite(factor)) throw MeshingError("VolumeMetricSpace: the length factor must be > 0");
  if (boundary.empty()) return;
  std::size_t slots = 16;
  while (4 * boundary.size() > 3 * slots) slots *= 2;  // load at most 3/4
  boundary_.assign(slots, kEmpty);
  mask_ = slots - 1;
  for (const Vec3& x : boundary) {
    const Key k = key(x);
    if (k == kEmpty) continue;  // not a finite point
    std::size_t i = hash(k) & mask_;
    while (boundary_[i] != kEmpty && boundary_[i] != k) i = (i + 1) & mask_;
    boundary_[i] = k;
  }
}

VolumeMetricSpace::Key VolumeMetricSpace::key(const Vec3& x) {
  // +0.0 for -0.0: the same point.
  return {std::bit_cast<std::uint64_t>(x.x() + 0.0), std::bit_cast<std::uint64_t>(x.y() + 0.0),
          std::bit_cast<std::uint64_t>(x.z() + 0.0)};
}

std::size_t VolumeMetricSpace::hash(const Key& k) {
  std::uint64_t h = k[0] * 0x9E3779B97F4A7C15ull;
  h = (h ^ (h >> 29) ^ k[1]) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 31) ^ k[2]) * 0x94D049BB133111EBull;
  return static_cast<std::size_t>(h ^ (h >> 32));
}

double VolumeMetricSpace::lengthFactor(const Vec3& x, const Metric3d& m) const {
  if (!surface_) return onBoundary(x) ? 1.0 : factor_;
  // Search radius: kVolumeTransitionLayers times the largest size of M(x), bounded above by
  // the Frobenius norm of the length tensor (a farther surface point is farther than the
  // transition in M).
  const double s = isotropicScale(m.matrix());
  const double hmax = s > 0 ? 1.0 / s : m.inverseMatrix().norm();
  const double radius = kVolumeTransitionLayers * hmax;
  // Certainly farther than the radius from the surface (so not a surface node either).
  if (surface_->beyond(x, radius)) return factor_;
  if (onBoundary(x)) return 1.0;
  Vec3 c;
  if (!surface_->closest(x, radius, c)) return factor_;
  const double t = std::min(1.0, m.length(x - c) / kVolumeTransitionLayers);
  return 1.0 + (factor_ - 1.0) * t;
}

double VolumeMetricSpace::lengthFactorFrom(const Vec3& x, const Mat3& mv) const {
  if (!surface_) return onBoundary(x) ? 1.0 : factor_;
  if (factor_ < 1) return lengthFactorAt(x);
  const double s = isotropicScale(mv);
  const double hv = s > 0 ? 1.0 / s : mv.inverse().norm();  // ≥ mv's largest size
  // A surface point farther than this gives f_max·|mv (x − c)| > L: f = f_max.
  const double reach = kVolumeTransitionLayers * hv / factor_;
  if (surface_->beyond(x, reach * (1 - kFactorSlack))) return factor_;
  if (onBoundary(x)) return 1.0;
  Vec3 c;
  if (!surface_->closest(x, reach * (1 + kFactorSlack), c)) return factor_;
  const double k = (mv * (x - c)).norm() / kVolumeTransitionLayers;
  if (factor_ * k >= 1) return factor_;
  return 1.0 / (1.0 - (factor_ - 1.0) * k);
}

bool VolumeMetricSpace::onBoundary(const Vec3& x) const {
  if (boundary_.empty()) return false;
  const Key k = key(x);
  for (std::size_t i = hash(k) & mask_;; i = (i + 1) & mask_) {
    if (boundary_[i] == k) return k != kEmpty;
    if (boundary_[i] == kEmpty) return false;
  }
}

std::shared_ptr<ControlSpace3d> buildVolumeControlSpace(const Model& model, const SurfaceMesh& surface, int solid,
                                                        const SizingParameters& sizing, const UserSizing* user,
                                                        const std::vector<std::vector<int>>* faceTriangles) {
  const std::vector<char> faces = solidFaces(model, solid);
  const double diag = model.diagonal();
  const double hmax = sizing.hmaxFor(diag), hmin = sizing.hminFor(diag);
  const double gammaA = std::max(1.0, sizing.anisotropy);

  // 4 (gathered first for the box): per boundary node, the blend of its triangles' metrics.
  // The solid's triangles in ascending surface order and its nodes in ascending index: the
  // same sums and insertions as a pass over the whole surface, in time and memory
  // proportional to the solid's own boundary (an assembly has many solids).
  std::vector<std::vector<int>> byFace;
  if (!faceTriangles) {
    byFace = trianglesByFace(surface, static_cast<int>(model.faces.size()));
    faceTriangles = &byFace;
  }
  std::vector<int> solidTriangles;
  for (std::size_t f = 0; f < faces.size() && f < faceTriangles->size(); ++f)
    if (faces[f]) solidTriangles.insert(solidTriangles.end(), (*faceTriangles)[f].begin(), (*faceTriangles)[f].end());
  std::sort(solidTriangles.begin(), solidTriangles.end());
  if (solidTriangles.empty())
    throw MeshingError("solid " + std::to_string(solid + 1) + ": no boundary triangle for the volume control space");
  std::vector<int> nodes;
  nodes.reserve(3 * solidTriangles.size());
  for (const int t : solidTriangles)
    for (const int v : surface.triangles[static_cast<std::size_t>(t)]) nodes.push_back(v);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const auto local = [&nodes](int v) {
    return static_cast<std::size_t>(std::lower_bound(nodes.begin(), nodes.end(), v) - nodes.begin());
  };
  std::vector<MetricBlend<3>> blend(nodes.size());
  Box3 box;
  for (const int t : solidTriangles) {
    const std::array<int, 3>& tri = surface.triangles[static_cast<std::size_t>(t)];
    for (const int v : tri) box.add(surface.nodes[v]);
    Metric3d m;
    if (!triangleMetric(surface.nodes[tri[0]], surface.nodes[tri[1]], surface.nodes[tri[2]], gammaA, hmin, m)) continue;
    for (const int v : tri) blend[local(v)].add(m, 1.0);
  }

  // 1–2
  const double margin = kVolumeBoxMargin * std::max(box.diagonal(), 1e-300);
  box.lo.array() -= margin;
  box.hi.array() += margin;
  auto cs = std::make_shared<CSOctree3d>(box, sizing);

  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (!blend[i].empty()) cs->insertDiscreteSource(surface.nodes[nodes[i]], blend[i].result());

  // h_max everywhere (and the user's global metric): folds in the point sources above. The
  // user's metrics are bounded to [h_min, h_max] (SizingParameters: hard bounds).
  const UserSizing userBounded = user ? user->bounded(hmin, hmax) : UserSizing{};
  user = &userBounded;
  Metric3d global = Metric3d::isotropic(hmax);
  if (user->global) global = intersect(global, *user->global);
  cs->setContinuousSource(CSAnalytic3d(box, [global](const Vec3&) { return global; }));

  // 3: the user's sources meeting the solid.
  if (user)
    for (const SizingSource& src : user->sources) {
      if (!src.faces.empty()) continue;  // a source of faces sizes those faces only
      const std::unique_ptr<ExtendedSource3d> ext = extendedSource(src);
      if (ext && overlaps(ext->bounds(), box)) cs->insertExtendedSource(*ext, src.metric);
    }
  if (user) insertSolidPoints(*cs, user->points, box);  // PointSizing.h

  // 5
  cs->modifyControlVertices([gammaA](const Vec3&, Metric3d& m) {
    if (anisotropyRatio(m) <= gammaA * (1 + 1e-9)) return false;
    m = limitAnisotropy(m, gammaA);
    return true;
  });
  cs->smoothGradation(volumeGradation(sizing.gradation, kVolumeLengthFactor));
  return cs;
}

}  // namespace aniso
