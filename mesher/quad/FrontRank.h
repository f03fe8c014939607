#pragma once
// The conversion front and the rank of its edges (thesis 4.7.1, eq. 4.4).
//
// During the conversion the live triangles form the unconverted region; a front edge is an
// edge of a live triangle whose other side is a quad or the face boundary, taken with the
// triangle on its left (the directed edge a→b of the triangle's corner list). The front
// cycles are the boundary of the region.
//
// rank(E_f) = Σ ω_i a_i (eq. 4.4) with
//   a_1 type: 0 when both side angles α_L (at a), α_R (at b) are below α_1 = 3π/4, 1 when
//       one is, 2 otherwise. α is the region's inner angle at the vertex between E_f and
//       the next front edge, summed over the region's triangles in metric space;
//   a_2 small side angle: 1 when α_L or α_R < α_2 = π/8;
//   a_3 level: 0 on the face boundary, the level of the quad across E_f plus 1 otherwise;
//   a_4 metric length: ⌊l_M²⌋ when l_M² > 2, else 0;
//   a_5 metric gradation: ⌊γ − 1⌋, γ ≥ 1 the ratio of E_f's metric lengths measured with
//       its two endpoints' metrics (VertexMetrics::gradation);
// weights ω = (1, 10, 1, 1, 1) (the thesis' choice). Lower ranks are converted first.
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

struct FrontWeights {
  double type = 1, smallAngle = 10, level = 1, length = 1, gradation = 1;
  double alpha1 = 2.35619449019234492885;  ///< 3π/4
  double alpha2 = 0.39269908169872415481;  ///< π/8
};

struct FrontEdgeClass {
  double alphaL = 0, alphaR = 0;  ///< inner angles of the region at a and at b (metric)
  int a1 = 0, a2 = 0, a3 = 0, a4 = 0, a5 = 0;
  double rank = 0;
};

/// Whether edge k of live triangle e is a front edge.
bool isFrontEdge(const QuadMesh2d& mesh, int e, int k);

/// The inner angle of the unconverted region at vertex v, starting at triangle e (which has
/// a front edge at v) and walking through the region's triangles counter-clockwise
/// (ccw = true) or clockwise, summing the metric angles at v.
double regionAngle(const QuadMesh2d& mesh, VertexMetrics& metrics, int v, int e, bool ccw);

/// Classifies front edge k of triangle e; `level` is its a_3.
FrontEdgeClass classifyFrontEdge(const QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, int level,
                                 const FrontWeights& w = {});

}  // namespace aniso::quad
