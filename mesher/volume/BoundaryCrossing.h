#pragma once
// boundaryCrossing — evidence that a solid's boundary mesh intersects itself, found while
// recovering it (BoundaryRecovery.h): a missing boundary edge whose pipe (Pipe.h, exact)
// crosses a boundary entity that IS present — the interior of a constrained boundary face,
// or a present boundary edge at a point interior to both. Two boundary entities then meet
// in their interiors: no tetrahedralization has both as faces/edges, and neither flips nor
// interior points recover it. Splitting the surface edges (new nodes on the CAD) can: where
// two curved faces are closer than the chords' sagitta; not where two faces of the solid
// overlap (docs/measurements.md).
#include <vector>

#include "mesher/volume/Pipe.h"
#include "mesher/volume/PipeReduction.h"

namespace aniso::volume {

/// The vertices of the first present boundary entity (2 for an edge, 3 for a constrained
/// face) crossed by the missing edge (a, b); empty when there is none. `isBoundaryEdge`
/// names boundary edges; `pipe` is scratch.
std::vector<del3d::VertexId> boundaryCrossing(const del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b,
                                              const EdgeGuard& isBoundaryEdge, Pipe& pipe);

}  // namespace aniso::volume
