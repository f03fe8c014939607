#pragma once
// splitCracks — the two sides of every crack face separate (ModelSolid::embedded with
// crack = true): after volume meshing a crack's triangles are faces of two tetrahedra of
// its solid, one on each side; this duplicates the crack's nodes so that the tetrahedra of
// one side use the copies.
//
// Which nodes: every node of a crack face's triangles except those on its front — the
// crack edges used by no other face of the solid (neither a boundary face nor another
// crack face), where the crack closes. Nodes on the mouth (crack edges on the solid's
// boundary) and on edges between crack faces are duplicated.
// How: around such a node, its solid's tetrahedra are grouped into the connected sets of
// tetrahedra sharing a face through the node that is not a crack triangle; the group
// holding the tetrahedron with the lowest index keeps the node, every other group gets
// a copy of its own (a node where cracks branch gets several). Copies are appended to the
// mesh's nodes (same position and NodeOn) in order of the original node and group.
// The surface: every crack triangle is kept for the side that holds its nodes as they are
// and gets a twin, reversed, on the copies of the other side (same face); every other
// surface triangle through a duplicated node takes the nodes of the one tetrahedron it
// is a face of. Linear meshes only (before order 2). Deterministic.
#include <array>
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/volume/VolumeMesh.h"

namespace aniso {

struct CrackSplitStats {
  int crackFaces = 0;       ///< crack faces with triangles in the mesh
  std::vector<int> faces;   ///< those faces (0-based), in solid then face order
  int nodesDuplicated = 0;  ///< copies made
  int trianglesAdded = 0;   ///< twin crack triangles
};

/// A crack triangle whose three nodes are on the front cannot open (no node of it is
/// doubled): the edges to split first (SplitSurfaceEdges.h, a new node on the CAD face), the
/// longest of each such triangle's edges not on the front.
std::vector<std::array<int, 2>> crackEdgesToOpen(const Model& model, const std::vector<std::vector<int>>& cracks,
                                                 const SurfaceMesh& surface);

/// Splits the crack faces of every solid with `crack` set (see above). `cracks[s]` lists
/// solid s's crack faces (0-based); faces of other solids are not affected.
CrackSplitStats splitCracks(const Model& model, const std::vector<std::vector<int>>& cracks, VolumeMesh& mesh);

}  // namespace aniso
