#include "io/ElementQuality.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "mesher/metric/MeanRatio.h"
#include "mesher/quad/QuadQuality.h"
#include "mesher/volume/TetQuality.h"

namespace aniso::io {
namespace {

/// Count, min, mean and equal bins over [0, 1] of one measure.
struct Tally {
  long long count = 0;
  double min = 0, sum = 0;
  std::array<long long, kQualityBins> bins{};
  void add(double v) {
    min = count ? std::min(min, v) : v;
    sum += v;
    ++count;
    const int b = static_cast<int>(std::floor(v * kQualityBins));
    ++bins[static_cast<std::size_t>(std::clamp(b, 0, kQualityBins - 1))];
  }
  nlohmann::ordered_json json(const char* measure) const {
    nlohmann::ordered_json j;
    j["count"] = count;
    j["measure"] = measure;
    j["min"] = min;
    j["mean"] = count ? sum / static_cast<double>(count) : 0.0;
    j["histogram"] = {{"lo", 0.0}, {"hi", 1.0}, {"bins", bins}};
    return j;
  }
};

/// Smallest interior angle of a triangle, degrees (0 for a degenerate one).
double triangleMinAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const std::array<Vec3, 3> p{a, b, c};
  double worst = 180;
  for (int k = 0; k < 3; ++k) {
    const Vec3 u = p[(k + 1) % 3] - p[k], v = p[(k + 2) % 3] - p[k];
    const double angle = std::atan2(u.cross(v).norm(), u.dot(v)) * 180 / std::numbers::pi;
    worst = std::min(worst, std::isfinite(angle) ? angle : 0.0);
  }
  return worst;
}

}  // namespace

nlohmann::ordered_json elementQuality(const SurfaceMesh& mesh) {
  Tally tri;
  double angleMin = 180;
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.nodes[t[0]], &b = mesh.nodes[t[1]], &c = mesh.nodes[t[2]];
    tri.add(meanRatio(a, b, c));
    angleMin = std::min(angleMin, triangleMinAngle(a, b, c));
  }
  nlohmann::ordered_json j = {{"type", "triangles"}};
  j.update(tri.json("mean_ratio"));
  j["angle_min"] = tri.count ? angleMin : 0.0;
  if (!mesh.quads.empty()) {
    Tally quad;
    for (const auto& q : mesh.quads)
      quad.add(quad::scaledJacobian3d(mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]], mesh.nodes[q[3]]));
    j["quads"] = quad.json("scaled_jacobian");
  }
  return j;
}

nlohmann::ordered_json elementQuality(const VolumeMesh& mesh) {
  Tally tet;
  double dihedralMin = 180;
  const std::vector<Vec3>& x = mesh.nodes();
  for (const auto& t : mesh.tets) {
    tet.add(tetMeanRatio(x[t[0]], x[t[1]], x[t[2]], x[t[3]]));
    dihedralMin = std::min(dihedralMin, tetDihedralRange(x[t[0]], x[t[1]], x[t[2]], x[t[3]]).minDeg);
  }
  nlohmann::ordered_json j = {{"type", "tetrahedra"}};
  j.update(tet.json("mean_ratio"));
  j["dihedral_min"] = tet.count ? dihedralMin : 0.0;
  return j;
}

}  // namespace aniso::io
