#include "mesher/volume/SurfaceGeometry.h"

#include <algorithm>
#include <map>
#include <span>
#include <utility>

#include <Eigen/Geometry>

#include "mesher/core/NodeBuckets.h"
#include "mesher/volume/SegmentCrossing.h"
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

/// Do triangles t and u (sharing at least one node) meet beyond what they share? Every edge
/// of one that is not an edge of the other, against the other (SegmentCrossing.h).
bool crossing(const SurfaceMesh& m, const std::array<int, 3>& t, const std::array<int, 3>& u) {
  const auto hasEdge = [](const std::array<int, 3>& x, int a, int b) {
    for (int k = 0; k < 3; ++k)
      if ((x[k] == a && x[(k + 1) % 3] == b) || (x[k] == b && x[(k + 1) % 3] == a)) return true;
    return false;
  };
  for (const auto& [x, y] : {std::pair{&t, &u}, std::pair{&u, &t}}) {
    const double *a = m.nodes[(*y)[0]].data(), *b = m.nodes[(*y)[1]].data(), *c = m.nodes[(*y)[2]].data();
    for (int k = 0; k < 3; ++k) {
      const int p = (*x)[k], q = (*x)[(k + 1) % 3];
      if (hasEdge(*y, p, q)) continue;
      if (volume::segmentCrossesTriangle(m.nodes[p].data(), m.nodes[q].data(), a, b, c) != volume::Cross::None) return true;
    }
  }
  return false;
}

/// Pairs of triangles around nodes on CAD vertices and edges that cross (header); each
/// pair once, (face, pairs) by face.
int crossingsNearEdges(const SurfaceMesh& m, std::vector<std::pair<int, int>>& byFace) {
  const auto watched = [&](int v) {
    return static_cast<std::size_t>(v) < m.nodeOn.size() &&
           (m.nodeOn[v].kind == NodeOn::Kind::Vertex || m.nodeOn[v].kind == NodeOn::Kind::Edge);
  };
  std::vector<std::pair<int, int>> uses;  // (watched node, triangle)
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (const int v : m.triangles[t])
      if (watched(v)) uses.emplace_back(v, static_cast<int>(t));
  NodeBuckets<std::pair<int, int>> around = bucketByNode(
      std::span<const std::pair<int, int>>(uses), m.nodes.size(), [](const std::pair<int, int>& u) { return u.first; });
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t v = 0; v < around.nodes(); ++v) {
    const std::span<std::pair<int, int>> b = around.bucket(v);
    for (std::size_t i = 0; i < b.size(); ++i)
      for (std::size_t j = i + 1; j < b.size(); ++j) {
        const int t = b[i].second, u = b[j].second;
        if (crossing(m, m.triangles[t], m.triangles[u])) pairs.emplace_back(std::min(t, u), std::max(t, u));
      }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::map<int, int> faces;
  for (const auto& [t, u] : pairs) {
    ++faces[m.triangleFace[static_cast<std::size_t>(t)]];
    if (m.triangleFace[static_cast<std::size_t>(u)] != m.triangleFace[static_cast<std::size_t>(t)])
      ++faces[m.triangleFace[static_cast<std::size_t>(u)]];
  }
  byFace.assign(faces.begin(), faces.end());
  return static_cast<int>(pairs.size());
}

}  // namespace

std::vector<std::string> SurfaceGeometryCheck::messages() const {
  std::vector<std::string> out;
  if (foldedEdges) out.push_back(std::to_string(foldedEdges) + " folded edges");
  if (flatTriangles) out.push_back(std::to_string(flatTriangles) + " flat triangles");
  if (openEdges) out.push_back(std::to_string(openEdges) + " open edges on closed shells");
  if (crossingPairs) out.push_back(std::to_string(crossingPairs) + " pairs of triangles crossing near CAD edges");
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
  c.crossingPairs = crossingsNearEdges(mesh, c.crossingFaces);
  return c;
}

}  // namespace aniso
