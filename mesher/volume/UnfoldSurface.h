#pragma once
// unfoldSurface — mends folds of the surface mesh before the volume is meshed.
//
// A folded edge is an edge shared by two triangles of one model face whose normals are
// more than about 84 degrees apart (kFoldCosine); neighbours on a face meshed within the
// curvature ratio differ by a few degrees. Folds appear where a face is nearly degenerate:
// a triangle spanning three nearly collinear rim nodes of a straight CAD edge stands
// across its face (90 degrees) and lies in the plane of the next face, a face node pushed
// across the rim folds its star over (180 degrees). Either way the solid's boundary
// overlaps itself, and no tetrahedralization contains it (boundary recovery, thesis 5.4,
// needs a boundary that does not cross itself).
//
// Mending: edge flips inside each face (never on a CAD edge: both triangles of a flipped
// edge belong to the face, so the rim and every face sharing it keep their triangles, and
// no node is added or removed), only where the quad is nearly flat. A flip of an edge of a triangle on a fold is kept only if
// it lowers the number of folded edges among the five edges of its quad and both new
// triangles are non-degenerate; the global count of folded edges strictly decreases, so
// the process ends. Folds no flip mends are re-triangulated as regions (FoldRegion.h).
// Faces in order, triangles in order: deterministic. The mesh must be linear (no mid
// nodes). A face whose triangles were re-triangulated moves to the end of the list.
#include <vector>

#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

struct UnfoldStats {
  int foldedBefore = 0;  ///< folded edges found
  int foldedAfter = 0;   ///< folded edges left
  int flips = 0;         ///< edges flipped
  int regions = 0;       ///< regions re-triangulated (FoldRegion.h)
  int nodesDropped = 0;  ///< face nodes left in no triangle by those
  std::vector<int> facesChanged;  ///< 0-based model faces whose triangles changed, in order
};

UnfoldStats unfoldSurface(SurfaceMesh& mesh);

/// Number of folded edges (see above) of the mesh's triangles.
int countFoldedEdges(const SurfaceMesh& mesh);
/// The same per face: (0-based face, folded edges) for every face that has some, by face.
std::vector<std::pair<int, int>> foldedEdgesByFace(const SurfaceMesh& mesh);

}  // namespace aniso
