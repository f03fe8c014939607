#include "mesher/quad/SharpCornerTriangles.h"

#include <Eigen/Geometry>
#include <cmath>

#include "mesher/quad/PoleTriangles.h"
#include "mesher/surface/contour/CornerParity.h"

namespace aniso::quad {
namespace {

/// The angle of triangle c at corner k, in 3D when every corner has a node, else in (u, v).
double cornerAngle(const QuadMesh2d& mesh, std::span<const Vec3> nodes, const Corners& c, int k) {
  const int v = c[k], a = c[(k + 1) % 3], b = c[(k + 2) % 3];
  const auto inNodes = [&](int x) { return mesh.node[x] >= 0 && static_cast<std::size_t>(mesh.node[x]) < nodes.size(); };
  if (inNodes(v) && inNodes(a) && inNodes(b)) {
    const Vec3 p = nodes[mesh.node[v]], da = nodes[mesh.node[a]] - p, db = nodes[mesh.node[b]] - p;
    return std::atan2(da.cross(db).norm(), da.dot(db));
  }
  const Vec2 da = mesh.uv[a] - mesh.uv[v], db = mesh.uv[b] - mesh.uv[v];
  return std::atan2(std::abs(da.x() * db.y() - da.y() * db.x()), da.dot(db));
}

}  // namespace

std::vector<Corners> detachSharpCornerTriangles(QuadMesh2d& mesh, std::span<const Vec3> nodes) {
  std::vector<int> elementsAt(mesh.numVertices(), 0);
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int k = 0; k < mesh.sides(e); ++k) ++elementsAt[mesh.corners[e][k]];
  std::vector<Corners> out;
  for (int e = 0; e < mesh.numElements(); ++e) {
    if (!mesh.isTriangle(e)) continue;
    const Corners c = mesh.corners[e];
    for (int k = 0; k < 3; ++k)
      if (mesh.boundary[c[k]] && elementsAt[c[k]] == 1 && cornerAngle(mesh, nodes, c, k) < contour::kQuadCornerAngle) {
        detachTriangle(mesh, e, out);
        break;
      }
  }
  return out;
}

}  // namespace aniso::quad
