#pragma once
// convertToQuads — the quad-dominant mesh of one face from its triangle mesh, in the face's
// parametric plane with its metric (thesis 4.7–4.8), run per face inside the parallel face
// pipeline of SurfaceMesher (--quad):
//   1 conversion by merging along the front (MergeConversion.h: eq. 4.4 ranks, alg. 4.4,
//     odd-cycle split);
//   2 pairing of the triangles left (TriangleTransport.h);
//   3 improvement, alg. 4.6 with N_imp passes: topological transformations
//     (QuadTopology.h) and metric Laplace smoothing (QuadSmoothing.h); the pairing is
//     repeated after each pass (smoothing opens cuts that were illegal before);
//   4 postprocessing of the elements adjacent to the boundary (BoundaryPostprocess.h,
//     thesis 4.8.3);
// The boundary is never changed: boundary vertices keep their (u, v) and node, boundary
// edges stay edges, so neighbouring faces stay conforming. With even segment counts on
// every loop (ContourOptions::evenSegments) the result is all-quad wherever the checks
// allow it; whatever cannot be converted legally stays a triangle.
#include "mesher/core/Cancel.h"
#include "mesher/control/ControlSpace2d.h"
#include "mesher/metric/QualityStats.h"
#include "mesher/quad/BoundaryPostprocess.h"
#include "mesher/quad/MergeConversion.h"
#include "mesher/quad/QuadSmoothing.h"
#include "mesher/quad/QuadTopology.h"
#include "mesher/quad/TriangleTransport.h"
#include "mesher/surface/FaceBoundary.h"

namespace aniso::quad {

struct QuadOptions {
  MergeOptions merge;
  TransportOptions transport;
  TopologyOptions topology;
  SmoothOptions smooth;
  BoundaryPostprocessOptions boundary;
  bool boundaryPostprocess = true;
  int improvementPasses = 2;  ///< N_imp (alg. 4.6, table 4.7)
  /// Checked between the conversion's steps and passes (Cancel.h); null: never stops.
  const CancelToken* cancel = nullptr;
};

struct QuadStats {
  MergeStats merge;
  int paired = 0, moves = 0, failedCuts = 0, failedPairs = 0, doublets = 0, swaps = 0, collapses = 0;
  long long smoothed = 0;
  BoundaryPostprocessStats boundary;
  int quads = 0, triangles = 0;
  QualityStats mu;            ///< μ_M: metric length of every edge of the result (eq. 2.49)
  QualityStats jacobian;      ///< metric scaled Jacobian per quad
  double seconds = 0;
};

/// Converts fm (triangles, as the face mesher left them) in place: fm.quads and the
/// triangles left, new inner vertices appended. Deterministic. Throws MeshingError only for
/// a structurally broken input mesh.
/// With `surface` (the face's), quads are judged by their 3D scaled Jacobian, the boundary
/// vertices at `nodes[node]` (the SurfaceMesh's nodes, see VertexMetrics).
QuadStats convertToQuads(FaceMesh& fm, const ControlSpace2d& cs, const ParametricSurface* surface = nullptr,
                         std::span<const Vec3> nodes = {}, const QuadOptions& options = {});

}  // namespace aniso::quad
