#include "mesher/volume/BoundaryTriangulation.h"

#include <algorithm>
#include <unordered_map>

#include "mesher/delaunay3d/Delaunay3d.h"

namespace aniso {

using del3d::VertexId;

BoundaryTriangulation triangulateBoundary(const SurfaceMesh& mesh, const BoundaryMesh& b) {
  BoundaryTriangulation out;
  out.tets.solid = b.solid;
  std::vector<Vec3> points;
  points.reserve(b.nodes.size());
  for (const int n : b.nodes) points.push_back(mesh.nodes[n]);
  del3d::DelaunayOptions opt;
  const del3d::DelaunayResult r = del3d::buildDelaunay(out.tets.mesh, points, opt);
  out.box = r.box;
  out.tets.node.assign(out.tets.mesh.numVertices(), -1);
  std::unordered_map<int, VertexId> vertexOfNode;
  vertexOfNode.reserve(b.nodes.size());
  for (std::size_t k = 0; k < b.nodes.size(); ++k) {
    const VertexId v = r.vertexOf[k];
    if (!v.valid() || out.tets.node[v.index] >= 0) {
      out.problems.push_back("solid " + std::to_string(b.solid + 1) + ": surface node " + std::to_string(b.nodes[k]) +
                             (v.valid() ? " coincides with node " + std::to_string(out.tets.node[v.index])
                                        : " could not be inserted"));
      continue;
    }
    out.tets.node[v.index] = b.nodes[k];
    vertexOfNode.emplace(b.nodes[k], v);
  }
  if (!out.problems.empty()) return out;
  SolidBoundary& sb = out.boundary;
  // Edges numbered in order of first use (a hash set of the vertex pairs: 3 lookups per
  // triangle).
  std::unordered_map<std::uint64_t, int> edgeIndex;
  edgeIndex.reserve(2 * b.triangles.size());
  sb.embeddedFrom = b.triangles.size();
  const std::size_t nt = b.triangles.size() + b.embedded.size();
  for (std::size_t t = 0; t < nt; ++t) {
    const bool embedded = t >= sb.embeddedFrom;
    const std::array<int, 3>& nodes = embedded ? b.embedded[t - sb.embeddedFrom] : b.triangles[t];
    std::array<VertexId, 3> tri;
    for (int k = 0; k < 3; ++k) tri[k] = vertexOfNode.at(nodes[k]);
    sb.triangles.push_back(tri);
    sb.triangleFace.push_back(embedded ? b.embeddedFace[t - sb.embeddedFrom] : b.triangleFace[t]);
    for (int k = 0; k < 3; ++k) {
      std::uint32_t p = tri[k].index, q = tri[(k + 1) % 3].index;
      if (p > q) std::swap(p, q);
      const std::uint64_t key = (std::uint64_t{p} << 32) | q;
      if (edgeIndex.emplace(key, static_cast<int>(sb.edges.size())).second) {
        sb.edges.push_back({VertexId(p), VertexId(q)});
        sb.edgeTriangle.push_back(static_cast<int>(t));
      }
    }
  }
  return out;
}

}  // namespace aniso
