#pragma once
// Local queries on the kernel's tetrahedralization used by boundary recovery and domain
// marking (thesis sec. 5.4): the star of a vertex, and whether an edge or a face is
// present. The mesh must have symmetric adjacency and valid vertex→tet references.
#include <array>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::volume {

/// The live tets incident to v (its star), by search across the faces containing v from
/// mesh.vertexTet(v). Empty when v is in no tet. Uses and clears the scratch mark B.
void vertexStar(const del3d::TetMesh& mesh, del3d::VertexId v, std::vector<del3d::TetId>& out);

/// A live tet containing both a and b (edge present) with their local indices; or an
/// invalid tet. `star` is scratch storage.
struct EdgeHandle {
  del3d::TetId tet;
  int i = -1, j = -1;
  bool valid() const { return tet.valid(); }
};
EdgeHandle findEdge(const del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b,
                    std::vector<del3d::TetId>& star);

/// A live tet having the face {a, b, c} (any order), with the face's local index; or an
/// invalid tet.
struct FaceHandle {
  del3d::TetId tet;
  int face = -1;
  bool valid() const { return tet.valid(); }
};
FaceHandle findFace(const del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b, del3d::VertexId c,
                    std::vector<del3d::TetId>& star);

/// findEdge / findFace with the star of a given (vertexStar(mesh, a, star), the mesh not
/// changed since): for many queries around one vertex.
EdgeHandle findEdgeInStar(const del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b,
                          const std::vector<del3d::TetId>& star);
FaceHandle findFaceInStar(const del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b, del3d::VertexId c,
                          const std::vector<del3d::TetId>& star);

}  // namespace aniso::volume
