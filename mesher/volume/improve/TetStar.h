#pragma once
// Star of a vertex in the 3D kernel's mesh: the live tets containing it, found by a walk
// from TetMesh::vertexTet across the faces that contain the vertex (sec. 5.6: smoothing
// and the quality measures work on vertex stars).
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::improve3d {

/// Fills `star` (cleared first) with the tets around v, starting at vertexTet(v); empty
/// when v is in no tet. Visited tets are kept in a small hash table (stars are small).
void vertexStar(const del3d::TetMesh& mesh, del3d::VertexId v, std::vector<del3d::TetId>& star);

}  // namespace aniso::improve3d
