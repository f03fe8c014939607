#pragma once
// Whether an edge of a SolidTetMesh lies on the solid's boundary (sec. 5.5.2: MLE only
// splits non-boundary edges). The hull of a SolidTetMesh is exactly its constrained
// boundary, so an edge is on the boundary iff the ring of tets around it is open; an edge
// with a free end is never on it.
#include "mesher/volume/SolidTetMesh.h"

namespace aniso::refine3d {

/// For the edge joining local vertices i and j of the live tet t.
bool isBoundaryEdge(const SolidTetMesh& s, del3d::TetId t, int i, int j);

}  // namespace aniso::refine3d
