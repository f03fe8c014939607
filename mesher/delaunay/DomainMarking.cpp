#include "mesher/delaunay/DomainMarking.h"

#include <unordered_set>

#include "mesher/core/Error.h"

namespace aniso::del2d {
namespace {

/// Flood fill from the triangles already set to `value` in `label` (listed in stack)
/// through unconstrained edges into triangles labelled `empty`.
template <class T>
void flood(const Triangulation2d& tri, std::vector<T>& label, std::vector<TriId>& stack, T value, T empty) {
  while (!stack.empty()) {
    const TriId t = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const TriId u = tri.neighbour(t, i);
      if (!u.valid() || tri.isConstrained(t, i) || label[u.index] != empty) continue;
      label[u.index] = value;
      stack.push_back(u);
    }
  }
}

}  // namespace

RegionLabels constrainedRegions(const Triangulation2d& tri) {
  RegionLabels r;
  r.region.assign(tri.triangleSlots(), kNone);
  std::vector<TriId> stack;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    if (!tri.isAlive(TriId(k)) || r.region[k] != kNone) continue;
    const auto id = static_cast<std::uint32_t>(r.count++);
    r.region[k] = id;
    stack.push_back(TriId(k));
    flood(tri, r.region, stack, id, kNone);
  }
  return r;
}

DomainMarks markDomain(const Triangulation2d& tri, std::span<const std::pair<VertexId, VertexId>> contour) {
  DomainMarks m;
  m.inside.assign(tri.triangleSlots(), 0);
  std::vector<TriId> stack;
  for (const auto& [a, b] : contour) {
    TriId t;
    int i = 0;
    if (!tri.findEdge(a, b, t, i)) {
      ++m.missingEdges;
      continue;
    }
    if (!m.inside[t.index]) {
      m.inside[t.index] = 1;
      stack.push_back(t);
    }
  }
  flood(tri, m.inside, stack, std::uint8_t{1}, std::uint8_t{0});
  // A slit (an edge in the contour both ways) has the domain on both sides; the contour's
  // edges are indexed only when a conflict is possible (faces without slits never do).
  std::unordered_set<std::uint64_t> directed;
  const auto key = [](VertexId a, VertexId b) { return (std::uint64_t{a.index} << 32) | b.index; };
  for (const auto& [a, b] : contour) {
    TriId t;
    int i = 0;
    if (!tri.findEdge(b, a, t, i) || !m.inside[t.index]) continue;
    if (directed.empty())
      for (const auto& [p, q] : contour) directed.insert(key(p, q));
    if (!directed.count(key(b, a))) ++m.conflicts;
  }
  for (std::uint8_t v : m.inside) m.insideCount += v;
  return m;
}

std::size_t removeTriangles(Triangulation2d& tri, std::span<const std::uint8_t> remove) {
  if (remove.size() < tri.triangleSlots())
    throw MeshingError("removeTriangles: the mask is shorter than the triangle slots");
  std::size_t removed = 0;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!remove[k] || !tri.isAlive(t)) continue;
    for (int i = 0; i < 3; ++i) {
      const TriId u = tri.neighbour(t, i);
      if (u.valid() && !remove[u.index]) {
        const int j = tri.neighbourIndex(u, t);
        if (j >= 0) tri.setNeighbour(u, j, TriId());
      }
      tri.setVertexTriangle(tri.vertex(t, i), TriId());
    }
    tri.freeTriangle(t);
    ++removed;
  }
  // Re-link the vertices that pointed to removed triangles.
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!tri.isAlive(t)) continue;
    for (int i = 0; i < 3; ++i) {
      const VertexId v = tri.vertex(t, i);
      if (!tri.vertexTriangle(v).valid()) tri.setVertexTriangle(v, t);
    }
  }
  return removed;
}

}  // namespace aniso::del2d
