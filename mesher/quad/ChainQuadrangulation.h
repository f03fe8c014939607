#pragma once
// Re-quadrangulation of a chain of elements between two triangles (the pairing of the
// triangles left by the conversion, thesis 4.7: all-quad wherever the counts allow it).
//
// A chain t1, q1, …, qn, t2 (consecutive elements sharing an edge, two triangles at the
// ends, quads between) covers a polygon of 3 + 2n + 1 = 2n + 4 vertices, so n + 1 quads can
// cover it exactly. When the union is a simple polygon whose outline holds every corner of
// the chain (no vertex inside it), its quadrangulations by inner diagonals are searched by
// dynamic programming over sub-polygons (quad (i, k, l, j) with every side a polygon edge
// or an inner diagonal, the three sub-polygons it leaves of even vertex count): the one
// whose worst quad is best (elementQuality, QuadShape.h), then the largest sum, is taken
// when its worst is at least minQuality. Ties by vertex order: deterministic.
// Check, then change: inner diagonals by exact orient2d (no proper crossing with the
// outline, locally inside at both ends), quads strictly convex and counter-clockwise; the
// outline is unchanged (no vertex added or moved), so nothing outside changes. Otherwise
// the mesh is untouched.
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

struct ChainOptions {
  double minQuality = 0.1;
  int maxVertices = 48;  ///< longer chains are not searched (the search is O(m⁴))
};

/// `chain`: live elements, consecutive ones adjacent, triangles at both ends and quads
/// between. Returns whether the chain was replaced by quads.
bool quadrangulateChain(QuadMesh2d& mesh, VertexMetrics& metrics, std::span<const int> chain,
                        const ChainOptions& options = {});

}  // namespace aniso::quad
