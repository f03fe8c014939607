#pragma once
// Discretization of the model's edges (thesis sec. 4.3, alg. 4.1) and the boundaries of the
// faces built from them.
//
// Each model edge is discretized once, into segments of unit length in the metric, the
// length of a piece being measured in the control spaces of EVERY face that uses the edge
// (the largest metric length wins, so the discretization conforms to all of them), with
// the last-segment adjustment of alg. 4.1 (the points are redistributed so that all
// segments have nearly equal metric length) and, on request, an even number of segments
// (for quad meshes). Its nodes (the two vertex nodes and the inner nodes) are created in
// the SurfaceMesh once and shared by all faces using the edge.
// Degenerate edges (poles) get one node (the vertex's) and are split in (u, v) only, into
// as many pieces as the face's metric (with the g_min guard) asks for.
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/model/Model.h"
#include "mesher/surface/FaceBoundary.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

struct EdgeDiscretization {
  std::vector<double> t;   ///< increasing from edge.t0 to edge.t1 (degenerate: along the pcurve)
  std::vector<int> nodes;  ///< SurfaceMesh nodes, same length as t
};

struct ContourOptions {
  bool evenSegments = false;  ///< --quad
  int minSegmentsClosedEdge = 3;  ///< a closed edge (v0 == v1) gets at least this many
};

/// Discretizes every edge used by a face. `faceSpaces[f]` is the control space of face f
/// (nullptr for a face that is not meshed). Vertex nodes are created first (one per model
/// vertex used), then edge nodes. Throws MeshingError naming the edge when its geometry
/// cannot be evaluated.
std::vector<EdgeDiscretization> discretizeEdges(const Model& model,
                                                const std::vector<const ControlSpace2d*>& faceSpaces,
                                                const ContourOptions& options, SurfaceMesh& mesh);

/// The boundary of face f from the edge discretizations (orientation normalised as
/// FaceBoundary documents).
FaceBoundary faceBoundary(const Model& model, int face, const std::vector<EdgeDiscretization>& edges,
                          const SurfaceMesh& mesh);

/// Adds a face mesh to the surface mesh: new nodes for the interior vertices (3D point
/// from the surface), triangles oriented with the face normal; triangles that collapse
/// in 3D (two corners on the same node, e.g. at a pole) are dropped.
void addFaceMesh(const Model& model, int face, const FaceMesh& fm, SurfaceMesh& mesh);

}  // namespace aniso
