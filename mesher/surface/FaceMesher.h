#pragma once
// FaceMesher — the anisotropic Delaunay triangulation of one face in its parametric plane
// (thesis ch. 4: 4.4 triangulation of boundary nodes, 4.5 insertion of inner nodes,
// 4.6 improvement), following the metric M = M_s M_p of the face's control space.
//
// Pipeline (each step its own unit in mesher/surface/face/):
//   1 boundary triangulation: the initial two triangles over the boundary's (u, v) box, the
//     boundary nodes inserted in random (spatially sorted) order with the in-circle test in
//     the metric of each inserted point (del2d::insertPoint);
//   2 recovery of the boundary edges missing from the triangulation (edge flips; a planar
//     straight-line graph never needs Steiner points), then each boundary edge constrained;
//   3 removal of the triangles outside the face by marking from the oriented loops
//     (holes, inner loops, seams, poles);
//   4 refinement (4.5): heap of triangles by q(K) = S_oI / S_oK (eq. 4.1) below q_t, and
//     of edges with l_M > 1.5; first a frontal phase (face/FrontalPoint.h, Rebay's frontal
//     Delaunay: the bad triangles on the front, next to a contour or an accepted triangle,
//     each refined by the point on its front edge), then the thesis' mixed MLE/CCS insertion
//     for the triangles left, with the cancellation rules (point outside the face, too
//     close to an existing vertex or to a contour in metric, metric jump), at most
//     4 NT_p + 1000 insertions in all (eq. 6.2; FaceMeshStats::insertionLimitReached);
//   5 improvement (4.6, improveFaceMesh): smoothing and swaps, N_imp passes;
//   6 unfolding (face/UnfoldFace.h) of what steps 1–3 left turned over on the surface;
//   7 flips and moves of triangles flat on the surface (face/FlatTriangles.h).
// With the face's surface given (FaceMesherOptions::surface), steps 4 and 5 make no
// triangle that is turned over in 3D (face/SurfaceLift.h: the fold guard).
// Boundary vertices never move and boundary edges are never flipped or split: the face
// mesh conforms exactly to the given boundary, so neighbouring faces stay conforming.
#include <functional>
#include <string>
#include <vector>

#include "mesher/core/Cancel.h"
#include "mesher/control/ControlSpace2d.h"
#include "mesher/geometry/ParametricSurface.h"
#include "mesher/surface/FaceBoundary.h"

namespace aniso {

struct FaceMesherOptions {
  double qualityThreshold = 0.58;   ///< q_t (table 4.4)
  double maxEdgeMetricLength = 1.5; ///< l_M above which an edge is split
  double mleToCcsQuality = 0.3;     ///< heap quality at which MLE switches to CCS (mixed method)
  int improvementPasses = 2;        ///< N_imp (alg. 4.2)
  bool innerAnglesCriterion = false;///< inner-angles Delaunay criterion (4.2.2) instead of the circumcircle
  unsigned seed = 12345;            ///< randomised boundary insertion order (deterministic)
  /// Predicted final triangle count while refining (face::RefineOptions::onPrediction).
  std::function<void(double)> onPrediction;
  /// The face's surface, in the (u, v) of the boundary (null for a planar analytic face
  /// whose (u, v) is its plane). When given, no operator may turn a triangle over in 3D
  /// (face/SurfaceOrientation.h), which a (u, v) test cannot see at singular points.
  const ParametricSurface* surface = nullptr;
  /// Checked between steps and every few hundred iterations (mesher/core/Cancel.h); null:
  /// never stops.
  const CancelToken* cancel = nullptr;
};

struct FaceMeshStats {
  int boundaryNodes = 0;
  int missingBoundaryEdges = 0;     ///< after boundary insertion, before recovery
  int insertedInner = 0;
  int cancelledInsertions = 0;
  int predictedTriangles = 0;         ///< NT_p (eq. 6.2) at the start of refinement
  /// Refinement stopped at its bound of 4 NT_p + 1000 insertions (the mesh is valid but may
  /// be coarser than the metric asks somewhere).
  bool insertionLimitReached = false;
  /// Triangles turned over on the surface (face/SurfaceLift.h) after refinement and
  /// improvement, mended by face::unfoldFace, and left (0 unless the face is degenerate).
  int foldsRepaired = 0, foldsLeft = 0;
  /// Triangles flat on the surface (face/FlatTriangles.h) before and after their removal.
  int flatTriangles = 0, flatTrianglesLeft = 0;
  double seconds = 0;
};

struct FaceMeshResult {
  FaceMesh mesh;
  FaceMeshStats stats;
  /// Empty on success; else what failed, e.g. "boundary edge (node 12, node 13) could not
  /// be recovered". The mesh is then empty.
  std::vector<std::string> problems;
  bool ok() const { return problems.empty(); }
};

/// Meshes one face. `cs` must cover the boundary's (u, v) box. Thread-safe for different
/// faces (cs is only read). Deterministic (fixed-seed insertion order, index-ordered heap).
/// Never throws for a meshing failure: it is reported in `problems`, naming the boundary
/// nodes involved — two nodes at the same (u, v), a boundary edge passing through a node
/// or crossing another boundary edge, loops that do not bound a region (orientation,
/// nesting), an exception of the control space — and the mesh is then empty. Throws
/// MeshingError only for invalid input: no loop, a loop with < 2 nodes, a non-finite (u, v).
/// Implementation: mesher/surface/face/ (one operator per file), improvement last.
FaceMeshResult meshFace(const FaceBoundary& boundary, const ControlSpace2d& cs,
                        const FaceMesherOptions& options = {});

}  // namespace aniso
