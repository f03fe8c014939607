#include "mesher/surface/face/SurfaceOrientation.h"

#include "mesher/surface/face/SurfaceLift.h"

namespace aniso::face {

bool collapsesAtPole(const FaceMesh& mesh, const std::array<int, 3>& v) {
  for (int i = 0; i < 3; ++i) {
    const int a = mesh.node[v[i]], b = mesh.node[v[(i + 1) % 3]];
    if (a >= 0 && a == b) return true;
  }
  return false;
}

std::vector<int> foldedTriangles(const FaceMesh& mesh, const ParametricSurface& s) {
  if (s.affine()) return {};  // (u, v) orientation is 3D orientation (validateFaceMesh checks it)
  const SurfaceLift lift(&s);
  std::vector<LiftedPoint> p(mesh.uv.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = lift.lift(mesh.uv[i]);
  std::vector<int> out;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    if (!collapsesAtPole(mesh, v) && !SurfaceLift::upright(p[v[0]], p[v[1]], p[v[2]]))
      out.push_back(static_cast<int>(t));
  }
  return out;
}

}  // namespace aniso::face
