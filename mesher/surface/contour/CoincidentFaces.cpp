#include "mesher/surface/contour/CoincidentFaces.h"

#include <algorithm>
#include <limits>
#include <map>

#include <Eigen/Geometry>

namespace aniso::contour {
namespace {

/// Triangles of each face sampled for the coincidence test.
constexpr std::size_t kSamples = 32;

Vec2 uvCentroid(const FaceMesh& m, const std::array<int, 3>& t) { return (m.uv[t[0]] + m.uv[t[1]] + m.uv[t[2]]) / 3.0; }

/// Every sampled triangle centre of `a` lies on the surface of `b` within tol.
bool liesOn(const ModelFace& fa, const FaceMesh& a, const ModelFace& fb, double tol) {
  const std::size_t n = a.triangles.size();
  if (n == 0) return false;
  const std::size_t step = std::max<std::size_t>(1, n / kSamples);
  Vec2 start = 0.5 * (fb.uvBounds.lo + fb.uvBounds.hi);
  for (std::size_t t = 0; t < n; t += step) {
    const Vec3 p = fa.surface->point(uvCentroid(a, a.triangles[t]));
    const Vec2 uv = fb.surface->project(p, start);
    const double d = (fb.surface->point(uv) - p).norm();
    if (!(d <= tol)) return false;
    start = uv;
  }
  return true;
}

std::vector<int> boundaryNodes(const FaceMesh& m) {
  std::vector<int> nodes;
  for (const int g : m.node)
    if (g >= 0) nodes.push_back(g);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace

std::vector<int> coincidentFaces(const Model& model, const std::vector<const FaceMesh*>& meshes) {
  const int nf = static_cast<int>(meshes.size());
  std::vector<int> twin(nf, -1);
  std::map<std::vector<int>, std::vector<int>> byBoundary;
  for (int g = 0; g < nf; ++g) {
    if (!meshes[g] || meshes[g]->triangles.empty() || !model.faces[g].surface) continue;
    std::vector<int> key = boundaryNodes(*meshes[g]);
    if (key.size() < 3) continue;
    std::vector<int>& earlier = byBoundary[std::move(key)];
    for (const int f : earlier) {
      const ModelFace &ff = model.faces[f], &fg = model.faces[g];
      const double tol = std::max(ff.tolerance, fg.tolerance);
      if (liesOn(fg, *meshes[g], ff, tol) && liesOn(ff, *meshes[f], fg, tol)) {
        twin[g] = f;
        break;
      }
    }
    if (twin[g] < 0) earlier.push_back(g);
  }
  return twin;
}

int shareFaceTriangles(const Model& model, int to, std::size_t first, std::size_t last, const FaceMesh& toMesh,
                       SurfaceMesh& mesh) {
  if (first >= last || toMesh.triangles.empty()) return 0;
  // orientation: `to`'s oriented normal at one of its triangles against the nearest
  // triangle of `from`
  const ModelFace& ft = model.faces[to];
  const Vec2 c = uvCentroid(toMesh, toMesh.triangles.front());
  const Vec3 p = ft.surface->point(c);
  const Vec3 n = ft.surface->normal(c) * (ft.reversed ? -1.0 : 1.0);
  std::size_t nearest = first;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t t = first; t < last; ++t) {
    const auto& tri = mesh.triangles[t];
    const double d = ((mesh.nodes[tri[0]] + mesh.nodes[tri[1]] + mesh.nodes[tri[2]]) / 3.0 - p).squaredNorm();
    if (d < best) best = d, nearest = t;
  }
  const auto& tn = mesh.triangles[nearest];
  const Vec3 area = (mesh.nodes[tn[1]] - mesh.nodes[tn[0]]).cross(mesh.nodes[tn[2]] - mesh.nodes[tn[0]]);
  const bool flip = area.dot(n) < 0;
  for (std::size_t t = first; t < last; ++t) {
    std::array<int, 3> tri = mesh.triangles[t];
    if (flip) std::swap(tri[1], tri[2]);
    mesh.triangles.push_back(tri);
    mesh.triangleFace.push_back(to);
  }
  return static_cast<int>(last - first);
}

}  // namespace aniso::contour
