#pragma once
// EdgeLengths — the measured edge lengths of a mesh, for the run report: what the sizing
// asked for (h_min, h_max; SizingParameters) set beside what the mesh has. Each edge counts
// once (shared by several elements or not).
#include <cstddef>

#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/VolumeMesh.h"

namespace aniso {

struct EdgeLengthRange {
  std::size_t edges = 0;  ///< distinct edges; 0: the other fields are 0
  double min = 0;
  double max = 0;
  double mean = 0;
};

/// The edges of the triangles and quads of a surface mesh.
EdgeLengthRange edgeLengths(const SurfaceMesh& mesh);
/// The edges of the tetrahedra of a volume mesh (its surface's edges are among them).
EdgeLengthRange edgeLengths(const VolumeMesh& mesh);

}  // namespace aniso
