#include "mesher/volume/SurfaceGeometry.h"

#include <algorithm>
#include <map>
#include <utility>

#include <Eigen/Geometry>

#include "mesher/volume/UnfoldSurface.h"

namespace aniso {
namespace {

bool flat(const SurfaceMesh& m, const std::array<int, 3>& t) {
  const Vec3 &a = m.nodes[t[0]], &b = m.nodes[t[1]], &c = m.nodes[t[2]];
  const double twiceArea = (b - a).cross(c - a).norm();
  const double longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return twiceArea <= kFlatTriangleRatio * longest;
}

/// Edges of solid s's shells used an odd number of times by its triangles and quads; 0 when
/// a face of s has no element.
long long openEdgesOfSolid(const Model& model, const std::vector<std::vector<int>>& byFace,
                           const std::vector<std::vector<int>>& quadsByFace, const SurfaceMesh& m, int s) {
  std::map<std::pair<int, int>, int> uses;
  for (const int f : model.solidFaces(s)) {
    if (f < 0 || static_cast<std::size_t>(f) >= byFace.size() || (byFace[f].empty() && quadsByFace[f].empty()))
      return 0;
    for (const int t : byFace[f])
      for (int k = 0; k < 3; ++k) ++uses[std::minmax(m.triangles[t][k], m.triangles[t][(k + 1) % 3])];
    for (const int q : quadsByFace[f])
      for (int k = 0; k < 4; ++k) ++uses[std::minmax(m.quads[q][k], m.quads[q][(k + 1) % 4])];
  }
  return std::count_if(uses.begin(), uses.end(), [](const auto& u) { return u.second % 2 != 0; });
}

}  // namespace

std::vector<std::string> SurfaceGeometryCheck::messages() const {
  std::vector<std::string> out;
  if (foldedEdges) out.push_back(std::to_string(foldedEdges) + " folded edges");
  if (flatTriangles) out.push_back(std::to_string(flatTriangles) + " flat triangles");
  if (openEdges) out.push_back(std::to_string(openEdges) + " open edges on closed shells");
  return out;
}

SurfaceGeometryCheck checkSurfaceGeometry(const Model& model, const SurfaceMesh& mesh) {
  SurfaceGeometryCheck c;
  c.foldedFaces = foldedEdgesByFace(mesh);
  for (const auto& [f, n] : c.foldedFaces) c.foldedEdges += n;
  std::vector<std::vector<int>> byFace(model.faces.size());
  std::map<int, int> flatByFace;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int f = mesh.triangleFace[t];
    if (flat(mesh, mesh.triangles[t])) {
      ++c.flatTriangles;
      ++flatByFace[f];
    }
    if (f >= 0 && static_cast<std::size_t>(f) < byFace.size()) byFace[f].push_back(static_cast<int>(t));
  }
  c.flatFaces.assign(flatByFace.begin(), flatByFace.end());
  std::vector<std::vector<int>> quadsByFace(model.faces.size());
  for (std::size_t q = 0; q < mesh.quads.size() && q < mesh.quadFace.size(); ++q)
    if (const int f = mesh.quadFace[q]; f >= 0 && static_cast<std::size_t>(f) < quadsByFace.size())
      quadsByFace[f].push_back(static_cast<int>(q));
  for (std::size_t s = 0; s < model.solids.size(); ++s)
    if (const long long n = openEdgesOfSolid(model, byFace, quadsByFace, mesh, static_cast<int>(s)); n > 0) {
      c.openEdges += n;
      c.openSolids.push_back({static_cast<int>(s), n});
    }
  return c;
}

}  // namespace aniso
