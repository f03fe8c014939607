#pragma once
// The recovery pipe (thesis sec. 5.4.1, Fig. 5.6): the mesh entities crossing a missing
// boundary edge or face. For a missing edge (a, b): the faces its interior pierces and the
// edges it crosses (coplanar, at one interior point). For a missing face (a, b, c) whose
// three edges are present: the edges crossing its interior (transversally, or lying in its
// plane). The region of tets explored is the stars of the entity's vertices plus every
// tet beside a crossing face or around a crossing edge. All decisions are exact
// (SegmentCrossing.h). `degenerate` flags a configuration no flip can mend: a vertex in
// the interior of the missing entity, or a collinear overlap.
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::volume {

struct FaceRef {
  del3d::TetId tet;
  int face = -1;
};
struct EdgeRef {
  del3d::TetId tet;
  int i = -1, j = -1;
};

struct Pipe {
  std::vector<FaceRef> faces;
  std::vector<EdgeRef> edges;
  std::vector<del3d::TetId> tets;  ///< the region explored (for face flips around the pipe)
  bool degenerate = false;
  /// Measure a flip must lower to be kept: a crossing edge counts twice (a T32 turns it
  /// into a crossing face), a crossing face once.
  int weight() const { return 2 * static_cast<int>(edges.size()) + static_cast<int>(faces.size()); }
};

void segmentPipe(const del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b, Pipe& pipe);
void trianglePipe(const del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b, del3d::VertexId c, Pipe& pipe);

}  // namespace aniso::volume
