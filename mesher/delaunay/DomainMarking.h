#pragma once
// Removal of obsolete triangles by marking (thesis sec. 4.4): "All elements directly
// adjacent to boundary contours are marked as valid, using the input geometry
// specification. The adjacency information is then used to propagate the marking to
// other valid triangles, avoiding trespassing of contours. After the iterative procedure
// is finished, all unmarked elements can be safely removed."
//
// The contours are the constrained edges (Triangulation2d::setConstrainedEdge); their
// recovery is the surface mesher's job. Check, then change: markDomain and
// constrainedRegions only read; removeTriangles changes.
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "mesher/delaunay/Triangulation2d.h"

namespace aniso::del2d {

/// Connected components of the live triangles through unconstrained edges (flood fill).
/// region[t] ∈ [0, count) per live slot, kNone for free slots.
struct RegionLabels {
  std::vector<std::uint32_t> region;
  std::size_t count = 0;
};
RegionLabels constrainedRegions(const Triangulation2d& tri);

struct DomainMarks {
  std::vector<std::uint8_t> inside;  ///< per triangle slot: 1 = valid (in the domain)
  std::size_t insideCount = 0;
  std::size_t missingEdges = 0;  ///< oriented edges that are not edges of the triangulation
  std::size_t conflicts = 0;     ///< oriented edges whose right side got marked too (open contour)
};

/// Marks the triangles on the left of each oriented contour edge a→b (the domain side
/// of counter-clockwise outer contours and clockwise holes) and propagates the marking
/// through unconstrained edges. The contour edges should be constrained; an unconstrained
/// contour edge lets the marking leak (reported through `conflicts`). An edge in the
/// contour in both directions (a slit) has the domain on both sides.
DomainMarks markDomain(const Triangulation2d& tri, std::span<const std::pair<VertexId, VertexId>> contour);

/// Removes every live triangle t with remove[t] != 0 (remove.size() ≥ triangleSlots()):
/// frees it, makes the edges it shared with kept triangles boundary edges (their
/// constrained bits stay) and re-links every vertex to a kept triangle (or to none).
/// Returns the number of triangles removed.
std::size_t removeTriangles(Triangulation2d& tri, std::span<const std::uint8_t> remove);

}  // namespace aniso::del2d
