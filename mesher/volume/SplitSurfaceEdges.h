#pragma once
// splitSurfaceEdges — the last resort of boundary recovery (thesis 5.4, table 5.3: Steiner
// points on the boundary) done where it keeps the mesh conformal: in the SURFACE mesh,
// before the solids are meshed again. Each given edge gets a new node at its middle ON THE
// CAD GEOMETRY (MidEdgeGeometry.h: on the model edge's curve when the edge runs along one,
// else on the face's surface), and every triangle using the edge is split: one split edge
// gives two triangles, two give three, three give four. Triangles keep their face and
// their orientation. Because the surface mesh is shared by every solid using the face, the
// solids meshed again from it stay conformal; a split edge is shorter and its diametral
// sphere smaller, so the Delaunay triangulation of the boundary nodes contains more of the
// boundary (the argument of conforming Delaunay refinement), and repeated splitting
// recovers any boundary.
//
// Edges are node pairs of the surface mesh (either order, duplicates allowed); pairs that
// are not an edge of a triangle are ignored, and so is an edge whose middle would land on a
// node already there (bit for bit: two edges of a fold over one point of the CAD; the
// Delaunay kernel cannot hold two nodes at one point). Edges of quads are not split (a quad-dominant
// mesh is a surface mesh only). The mesh must be linear (no mid nodes yet).
#include <array>
#include <span>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

struct SplitStats {
  int edgesSplit = 0;
  int trianglesBefore = 0, trianglesAfter = 0;
};

SplitStats splitSurfaceEdges(const Model& model, SurfaceMesh& mesh, std::span<const std::array<int, 2>> edges);

/// The edges to split for a boundary face (triangle) that could not be recovered although
/// its edges were: its longest edge (in 3D).
std::array<int, 2> longestEdge(const SurfaceMesh& mesh, const std::array<int, 3>& triangle);

}  // namespace aniso
