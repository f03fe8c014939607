#pragma once
// Metric Laplace smoothing of a mixed quad/triangle face mesh (thesis 4.8.2: the mixed
// approach of the triangle improvement, sec. 4.6.1, eq. 4.2–4.3, see
// improve/LaplaceSmoothing.h). Each sweep visits the inner vertices in index order
// (Gauss–Seidel). The target of Q with edge neighbours P_i is Q + S_Q⁻¹ (1/n) Σ S_i (P_i − Q),
// S_i the mean of S_Q and S_{P_i} scaled to det S_Q (only the shape of the metric varies,
// as in the triangle smoothing) — the plain average (eq. 4.2) when the metric is constant.
// Check, then change: the move is accepted when every element around Q stays strictly
// convex and counter-clockwise (exact) and the elements get better in metric
// (elementQuality): a poor star (worst below qualityFloor) must raise its worst, another
// must keep its worst ≥ qualityFloor (its mean may drop: the mean condition of the triangle
// smoothing gave poorer quads, docs/measurements.md); else
// the half move is tried. In any case no quad of the star may end below minQuadQuality
// (the star's worst may be a triangle, whose shape is another measure).
// Boundary vertices never move, nor do the vertices of elements touching a pole (two
// corners on one global node), whose metric the face's parameterization cannot represent.
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

struct SmoothOptions {
  int sweeps = 4;
  double qualityFloor = 0.4;
  double minQuadQuality = 0.1;  ///< no move takes a quad of the star below this (or lower)
};

struct SmoothStats {
  long long moved = 0, rejected = 0;
};

SmoothStats smoothQuadMesh(QuadMesh2d& mesh, VertexMetrics& metrics, const SmoothOptions& options = {});

/// Vertex → live elements, compressed rows (rebuilt by the operators that need it).
struct VertexElements {
  std::vector<int> start, elements;
  void build(const QuadMesh2d& mesh);
  std::span<const int> of(int v) const {
    return {elements.data() + start[v], static_cast<std::size_t>(start[v + 1] - start[v])};
  }
};

/// Quality of the elements of a star (elementQuality): worst, mean, worst quad (triangles
/// count by their shape, not a scaled Jacobian); `valid` false when one is not strictly
/// convex and counter-clockwise (its quality ≤ 0, so the worst is ≤ 0 too).
struct StarQuality {
  double worst = 2, mean = 0;
  double worstQuad = 2;
  bool valid = true;
};
StarQuality starQuality(const QuadMesh2d& mesh, VertexMetrics& metrics, std::span<const int> star);

/// Vertices that must not move: on the boundary, or corners of an element touching a pole.
std::vector<std::uint8_t> frozenVertices(const QuadMesh2d& mesh);

}  // namespace aniso::quad
