#include "mesher/surface/face/DomainRemoval.h"

#include <utility>

#include "mesher/delaunay/DomainMarking.h"

namespace aniso::face {

using namespace del2d;

std::vector<std::string> removeOutside(Triangulation2d& tri, const FlatBoundary& boundary,
                                       const std::vector<VertexId>& vertexOf, std::size_t* removed) {
  std::vector<std::string> problems;
  std::vector<std::pair<VertexId, VertexId>> contour;
  contour.reserve(boundary.size());
  for (std::uint32_t k = 0; k < boundary.size(); ++k) contour.emplace_back(vertexOf[k], vertexOf[boundary.next[k]]);
  const DomainMarks marks = markDomain(tri, contour);
  if (marks.missingEdges > 0)
    problems.push_back(std::to_string(marks.missingEdges) + " boundary edge(s) missing from the triangulation");
  if (marks.conflicts > 0)
    problems.push_back("the boundary loops do not bound a region consistently (" + std::to_string(marks.conflicts) +
                       " edge(s) have the face on both sides: wrong loop orientation or crossing/nested loops)");
  bool cornerInside = false;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!marks.inside[k] || !tri.isAlive(t)) continue;
    for (int i = 0; i < 3; ++i) cornerInside |= tri.isCorner(tri.vertex(t, i));
  }
  if (cornerInside)
    problems.push_back("the boundary loops leave the face unbounded in (u, v) (outer loop clockwise?)");
  if (marks.insideCount == 0) problems.push_back("no triangle lies inside the boundary loops");
  if (!problems.empty()) return problems;
  std::vector<std::uint8_t> remove(tri.triangleSlots(), 0);
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) remove[k] = marks.inside[k] ? 0 : 1;
  const std::size_t n = removeTriangles(tri, remove);
  if (removed != nullptr) *removed = n;
  return problems;
}

}  // namespace aniso::face
