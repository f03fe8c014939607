#include "mesher/sizing/VolumeChordBound.h"

#include <algorithm>
#include <cmath>

#include <exception>

#include <Eigen/Geometry>

namespace aniso {
namespace {

/// How much of the face bulges out of the solid (its chords cut into the solid) less how
/// much bulges in, in [−1, 1]: the sign of its mean curvature against the solid's outward
/// normal, sampled on a kConvexitySamples² grid of its parametric box, weighted by area;
/// `use` is its place in the shell. 0 for a plane.
constexpr int kConvexitySamples = 5;
double convexity(const ModelFace& f, const FaceUse& use) {
  if (!f.surface || f.surface->affine() || f.uvBounds.empty()) return 0;
  double net = 0, all = 0;
  for (int i = 0; i < kConvexitySamples; ++i)
    for (int j = 0; j < kConvexitySamples; ++j) {
      const Vec2 uv = f.uvBounds.lo + Vec2((i + 0.5) / kConvexitySamples, (j + 0.5) / kConvexitySamples)
                                          .cwiseProduct(f.uvBounds.hi - f.uvBounds.lo);
      const SurfaceD1 d = f.surface->d1(uv);
      const double w = d.pu.cross(d.pv).norm();
      if (!(std::isfinite(w) && w > 0)) continue;
      // k1, k2 are signed against normal(): negative where the surface bends away from it
      const PrincipalCurvatures pc = f.surface->curvature(uv);
      const double mean = use.reversed ? -(pc.k1 + pc.k2) : pc.k1 + pc.k2;
      net += mean < 0 ? w : mean > 0 ? -w : 0;
      all += w;
    }
  return all > 0 ? net / all : 0;
}

}  // namespace

double volumeChordDeviation(const Model& model, double chord) {
  if (!(chord > 0)) return chord;
  double volume = 0, bulge = 0;
  for (const ModelSolid& solid : model.solids) {
    if (!(solid.cadVolume > 0)) return chord;
    std::vector<int> shells = solid.voidShells;
    shells.push_back(solid.outerShell);
    double b = 0;  // convex minus concave curved area
    for (const int sh : shells) {
      if (sh < 0 || static_cast<std::size_t>(sh) >= model.shells.size()) continue;
      for (const FaceUse& use : model.shells[static_cast<std::size_t>(sh)].faces) {
        if (use.face < 0 || static_cast<std::size_t>(use.face) >= model.faces.size()) continue;
        const ModelFace& f = model.faces[static_cast<std::size_t>(use.face)];
        if (!(f.cadArea > 0)) return chord;
        try {
          b += convexity(f, use) * f.cadArea;
        } catch (const std::exception&) {
          return chord;  // a surface that cannot be evaluated: no estimate
        }
      }
    }
    volume += solid.cadVolume;
    bulge += std::abs(b);
  }
  if (!(bulge > 0)) return chord;
  const double bound = kVolumeChordRatio * volume / bulge;
  return std::isfinite(bound) ? std::min(chord, bound) : chord;
}

}  // namespace aniso
