#pragma once
// SolidTetMesh — the working tetrahedralization of ONE solid between the phases of the
// volume mesher (thesis ch. 5): boundary triangulation and recovery (5.3–5.4) produce it,
// refinement (5.5) and improvement (5.6) change it, VolumeMesher turns it into tetrahedra
// of the VolumeMesh. Solids are meshed independently (and in parallel): conformity across
// an assembly comes from the shared surface mesh, whose nodes are never moved or removed.
//
// Invariants between phases (checked by validateSolidTetMesh):
//  - `mesh` holds only this solid's tetrahedra (exterior, void and box tets removed);
//  - every boundary triangle of the solid is a face of exactly one live tet and carries the
//    constrained bit; every embedded triangle (BoundaryMesh::embedded) is a face of two live
//    tets, constrained in both; no other face is constrained; the hull of `mesh` is exactly
//    the set of boundary triangles — and of `patchFaces` when recovery left holes
//    (CarveAroundHoles.h: the caller then validates with the triangles kept);
//  - node[v] >= 0 for a kernel vertex that is a node of the surface mesh (its index there):
//    such vertices are FIXED (never moved, never removed); node[v] == -1 for vertices made
//    by the volume mesher (refinement points, Steiner points inside the solid): free to
//    move or remove, unless `pinned` (the vertices of patch faces): FIXED too; the eight
//    enclosing-box corners have node == -1 and are in no tet.
//  - every live tet positively oriented (exact orient3d).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso {

struct SolidTetMesh {
  int solid = -1;                 ///< 0-based model solid
  del3d::TetMesh mesh;
  std::vector<int> node;          ///< per kernel vertex: surface mesh node, or -1 (see above)
  /// Per kernel vertex (shorter: the rest not pinned): a vertex of a patch face.
  std::vector<std::uint8_t> pinned;
  /// Hull faces that are no boundary triangle (CarveAroundHoles.h), as sorted kernel
  /// vertex triples; constrained like boundary triangles. Empty but for a solid with holes.
  std::vector<std::array<std::uint32_t, 3>> patchFaces;

  bool isFixed(del3d::VertexId v) const {
    return (v.index < node.size() && node[v.index] >= 0) || (v.index < pinned.size() && pinned[v.index] != 0);
  }
  /// Adds a free vertex (created inside the solid) to the kernel and to `node`.
  del3d::VertexId addFreeVertex(const Vec3& p) {
    const del3d::VertexId v = mesh.addVertex(p);
    node.resize(mesh.numVertices(), -1);
    return v;
  }
};

/// Checks the invariants above (plus del3d::validate of the kernel), one message per
/// problem; empty when valid. `boundaryTriangles` and `embeddedTriangles` are the solid's
/// boundary and embedded triangles as surface mesh node triples (any orientation).
std::vector<std::string> validateSolidTetMesh(const SolidTetMesh& s,
                                              const std::vector<std::array<int, 3>>& boundaryTriangles,
                                              const std::vector<std::array<int, 3>>& embeddedTriangles = {});

}  // namespace aniso
