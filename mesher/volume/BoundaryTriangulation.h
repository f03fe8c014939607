#pragma once
// Triangulation of the boundary nodes of one solid (thesis sec. 5.3, alg. 5.2 with
// q_Bt = 0): del3d::buildDelaunay of the solid's boundary nodes — enclosing box, BRIO +
// Hilbert insertion order, exact Bowyer–Watson — giving the SolidTetMesh that boundary
// recovery (5.4) then constrains. The box stays (recovery may need the room outside the
// solid); DomainMarking removes it with the other exterior tets.
//
// Also translates the boundary into kernel vertex ids (SolidBoundary), with each distinct
// boundary edge once, for recovery and marking.
#include <array>
#include <string>
#include <vector>

#include "mesher/delaunay3d/EnclosingBox.h"
#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/BoundaryMesh.h"
#include "mesher/volume/SolidTetMesh.h"

namespace aniso {

struct SolidBoundary {
  /// The boundary triangles (outward, kernel ids), then the embedded faces' triangles
  /// (BoundaryMesh::embedded): from index `embeddedFrom` on. Recovery constrains all of
  /// them; only the boundary ones have an inside (carving).
  std::vector<std::array<del3d::VertexId, 3>> triangles;
  std::size_t embeddedFrom = 0;
  bool isEmbedded(std::size_t t) const { return t >= embeddedFrom; }
  std::vector<int> triangleFace;                          ///< 0-based model face
  std::vector<std::array<del3d::VertexId, 2>> edges;      ///< each undirected edge once
  std::vector<int> edgeTriangle;                          ///< one triangle using each edge
};

struct BoundaryTriangulation {
  SolidTetMesh tets;
  SolidBoundary boundary;
  del3d::EnclosingBox box;
  /// Nodes that could not be inserted (a duplicate position, a refused insertion), naming
  /// their faces; empty on success.
  std::vector<std::string> problems;
};

/// Builds the Delaunay triangulation of b's nodes (coordinates from `mesh`). Throws
/// MeshingError only when the kernel does (no finite point).
BoundaryTriangulation triangulateBoundary(const SurfaceMesh& mesh, const BoundaryMesh& b);

}  // namespace aniso
