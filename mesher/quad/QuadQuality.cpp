#include "mesher/quad/QuadQuality.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Geometry>

namespace aniso::quad {

double scaledJacobian3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const std::array<Vec3, 4> p{a, b, c, d};
  std::array<Vec3, 4> cross;
  Vec3 normal = Vec3::Zero();
  for (int k = 0; k < 4; ++k) {
    cross[k] = (p[(k + 1) % 4] - p[k]).cross(p[(k + 3) % 4] - p[k]);
    normal += cross[k];
  }
  double worst = 1.0;
  for (int k = 0; k < 4; ++k) {
    const double den = (p[(k + 1) % 4] - p[k]).norm() * (p[(k + 3) % 4] - p[k]).norm();
    if (!(den > 0)) return -1.0;
    const double sine = cross[k].norm() / den;
    worst = std::min(worst, cross[k].dot(normal) >= 0 ? sine : -sine);
  }
  return std::isfinite(worst) ? worst : -1.0;
}

SurfaceQuadQuality surfaceQuadQuality(const SurfaceMesh& mesh) {
  SurfaceQuadQuality q;
  const double total = static_cast<double>(mesh.quads.size() + mesh.triangles.size());
  q.fraction = total > 0 ? static_cast<double>(mesh.quads.size()) / total : 0.0;
  for (const auto& e : mesh.quads) {
    const double sj = scaledJacobian3d(mesh.nodes[e[0]], mesh.nodes[e[1]], mesh.nodes[e[2]], mesh.nodes[e[3]]);
    q.jacobian.add(sj);
    if (std::any_of(e.begin(), e.end(), [&](int n) {
          const NodeOn::Kind k = mesh.nodeOn[n].kind;
          return k == NodeOn::Kind::Vertex || k == NodeOn::Kind::Edge;
        }))
      q.boundaryJacobian.add(sj);
  }
  return q;
}

}  // namespace aniso::quad
