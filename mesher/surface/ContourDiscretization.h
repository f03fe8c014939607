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
// as many pieces as the face's metric asks for one mesh size away from the pole (at the
// pole itself only the g_min guard of M_p gives it a length, which would leave the face
// mesher one piece to fan from and fold the triangles around the pole in 3D).
//
// Precisely: the density along edge e is ρ(t) = max_k |M_k(c_k(t)) c_k'(t)| over its
// pcurves c_k on meshed faces (M_k = M_s M_p of that face's control space, queried at c_k(t)
// moved by whole periods into the space's bounds), integrated adaptively
// (contour/MetricArcLength.h); n = max(1, round(∫ρ)) segments, then raised where needed for
// a valid boundary: a closed edge gets at least max(3, minSegmentsClosedEdge); of several
// single-segment edges joining the same two vertices only the shortest stays single; every
// loop of a meshed face gets at least 3 segments; with evenSegments odd counts get one more,
// then faces with an odd number of corners too sharp for a quad get an odd boundary count
// (contour/CornerParity.h).
// The nodes are at equal metric arc length, plus (triangles only) one on an edge where a
// loop corner of one of its faces comes within the chord error of it
// (contour/VertexNearEdge.h). Deterministic.
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
  int minSegmentsClosedEdge = 3;  ///< a closed edge (v0 == v1) gets at least this many (never fewer than 3)
};

/// Discretizes every edge used by a loop of a meshed face. `faceSpaces[f]` is the control
/// space of face f (nullptr for a face that is not meshed); one entry per model face.
/// Vertex nodes are created first (one per model vertex used, in vertex order), then the
/// inner nodes of every edge (edge order, increasing t; 3D point from the edge's curve,
/// NodeOn Edge with t). Returns one entry per model edge, empty for edges not discretized.
/// Throws EntityError (kind Edge, its index) naming the edge when its geometry or metric
/// cannot be evaluated (no pcurve on a meshed face, empty parameter range, non-finite
/// metric), and MeshingError for a faceSpaces of the wrong size.
std::vector<EdgeDiscretization> discretizeEdges(const Model& model,
                                                const std::vector<const ControlSpace2d*>& faceSpaces,
                                                const ContourOptions& options, SurfaceMesh& mesh);

/// The boundary of face f from the edge discretizations (orientation normalised as
/// FaceBoundary documents). Node uv = c_p(t) on the use's pcurve; an inner edge node whose
/// p(c_p(t)) misses it by more than twice the CAD tolerance (pcurve not parameterized like
/// the 3D curve) is projected onto p∘c_p instead. On a periodic surface each use is moved
/// by whole periods to continue the previous one, then each loop as a whole to overlap the
/// face's uvBounds (outer loop) or the outer loop (holes). Throws MeshingError naming the
/// face and loop when an edge of the face was not discretized, when consecutive uses do
/// not share their vertex, or when a junction (the closing one included) stays open in
/// (u, v) by more than 1% of the face's parametric extent (10% when the two ends are one
/// point in 3D within the CAD tolerance).
FaceBoundary faceBoundary(const Model& model, int face, const std::vector<EdgeDiscretization>& edges,
                          const SurfaceMesh& mesh);

/// Adds a face mesh to the surface mesh: new nodes for the interior vertices (3D point
/// from the surface, NodeOn Face with uv), triangles oriented with the face normal
/// (flipped for a reversed face) and tagged with the face; triangles that collapse in 3D
/// (two corners on the same node, e.g. at a pole) are dropped. Throws MeshingError naming
/// the face for an inconsistent FaceMesh (sizes, indices out of range).
void addFaceMesh(const Model& model, int face, const FaceMesh& fm, SurfaceMesh& mesh);

}  // namespace aniso
