#include "mesher/surface/face/ValidateFaceMesh.h"

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <utility>

#include "mesher/predicates/Predicates.h"

namespace aniso::face {
namespace {

class Report {
 public:
  Report(std::vector<std::string>& out, std::size_t max) : out_(out), max_(max) {}
  bool full() const { return out_.size() >= max_; }
  template <class... A>
  void add(const A&... parts) {
    if (full()) return;
    std::ostringstream s;
    (s << ... << parts);
    out_.push_back(s.str());
  }

 private:
  std::vector<std::string>& out_;
  std::size_t max_;
};

using DirectedEdge = std::pair<std::uint32_t, std::uint32_t>;

bool hasEdge(const std::vector<DirectedEdge>& sorted, const DirectedEdge& e) {
  return std::binary_search(sorted.begin(), sorted.end(), e);
}

}  // namespace

std::vector<std::string> validateFaceMesh(const FaceMesh& mesh, const FaceBoundary& boundary, std::size_t maxProblems) {
  std::vector<std::string> out;
  Report r(out, maxProblems);
  const std::size_t nv = mesh.uv.size();
  if (mesh.node.size() != nv) r.add("uv has ", nv, " entries but node has ", mesh.node.size());
  // Boundary vertices and edges.
  std::vector<DirectedEdge> boundaryEdges;
  std::uint32_t k = 0;
  for (const auto& loop : boundary.loops) {
    const std::uint32_t begin = k;
    for (std::size_t i = 0; i < loop.size(); ++i, ++k) {
      if (k >= nv || k >= mesh.node.size()) {
        r.add("boundary vertex ", k, " missing");
        continue;
      }
      if (mesh.uv[k] != loop[i].uv || mesh.node[k] != loop[i].node)
        r.add("vertex ", k, " is not boundary node ", loop[i].node, " at its (u, v)");
      boundaryEdges.emplace_back(k, i + 1 < loop.size() ? k + 1 : begin);
    }
  }
  const std::uint32_t nb = k;
  for (std::size_t v = nb; v < mesh.node.size(); ++v)
    if (mesh.node[v] != -1) r.add("interior vertex ", v, " has node ", mesh.node[v], " (expected -1)");
  // Triangles.
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * mesh.triangles.size());
  std::vector<std::uint8_t> used(nv, 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tr = mesh.triangles[t];
    bool ok = true;
    for (int i = 0; i < 3; ++i) ok &= tr[i] >= 0 && static_cast<std::size_t>(tr[i]) < nv;
    if (!ok) {
      r.add("triangle ", t, " has a vertex out of range");
      continue;
    }
    if (tr[0] == tr[1] || tr[1] == tr[2] || tr[0] == tr[2]) {
      r.add("triangle ", t, " repeats a vertex");
      continue;
    }
    if (predicates::orient2d(mesh.uv[tr[0]].data(), mesh.uv[tr[1]].data(), mesh.uv[tr[2]].data()) <= 0)
      r.add("triangle ", t, " (", tr[0], ",", tr[1], ",", tr[2], ") is not counter-clockwise in (u, v)");
    for (int i = 0; i < 3; ++i) {
      used[tr[i]] = 1;
      edges.emplace_back(static_cast<std::uint32_t>(tr[i]), static_cast<std::uint32_t>(tr[(i + 1) % 3]));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 1; i < edges.size(); ++i)
    if (edges[i] == edges[i - 1]) r.add("directed edge (", edges[i].first, ",", edges[i].second, ") used twice");
  std::vector<DirectedEdge> sortedBoundary = boundaryEdges;
  std::sort(sortedBoundary.begin(), sortedBoundary.end());
  for (const DirectedEdge& e : edges)
    if (!hasEdge(edges, {e.second, e.first}) && !hasEdge(sortedBoundary, e))
      r.add("edge (", e.first, ",", e.second, ") is on the mesh boundary but is not a boundary edge");
  for (const DirectedEdge& e : boundaryEdges) {
    if (!hasEdge(edges, e)) r.add("boundary edge (", e.first, ",", e.second, ") is not an edge of a triangle");
    if (hasEdge(edges, {e.second, e.first}))
      r.add("boundary edge (", e.first, ",", e.second, ") has a triangle outside the face");
  }
  for (std::size_t v = nb; v < nv; ++v)
    if (!used[v]) r.add("interior vertex ", v, " is used by no triangle");
  return out;
}

}  // namespace aniso::face
