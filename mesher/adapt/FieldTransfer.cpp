#include "mesher/adapt/FieldTransfer.h"

#include <algorithm>

#include "mesher/adapt/CellLocator.h"
#include "mesher/core/Error.h"

namespace aniso {

TransferredField transferField(const PatchMesh& old, const std::vector<double>& values, int components,
                               const std::vector<Vec3>& points) {
  if (components < 1 || values.size() != old.nodes.size() * static_cast<std::size_t>(components))
    throw MeshingError("transferField: " + std::to_string(values.size()) + " values for " +
                       std::to_string(old.nodes.size()) + " nodes of " + std::to_string(components) + " components");
  if (old.cellCount() == 0) throw MeshingError("transferField: the old mesh has no cells");
  const CellLocator locator(old);
  TransferredField out;
  out.values.assign(points.size() * components, 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CellHit h = locator.locate(points[i]);
    if (h.distance > 0) {
      ++out.outside;
      out.maxDistance = std::max(out.maxDistance, h.distance);
    }
    const int* v = old.conn.data() + old.offsets[h.cell];
    for (int k = 0; k < old.corners(); ++k)
      for (int c = 0; c < components; ++c)
        out.values[i * components + c] += h.bary[k] * values[static_cast<std::size_t>(v[k]) * components + c];
  }
  return out;
}

}  // namespace aniso
