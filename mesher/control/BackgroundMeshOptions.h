#pragma once
// BackgroundMeshOptions — the choices of the background-mesh control spaces (CSMesh2d,
// CSMesh3d, thesis sec. 3.4) beyond the thesis' thresholds ε_M, ε_δ, l_Mmax (those come
// in SizingParameters, as for the quadtree / octree).
//
// Interpolation sets (sec. 3.4.5, fig. 3.6), all with the inverse squared-distance
// weights of eq. 3.2 and the ε_M shortcut:
//   Single         A_s — the nearest vertex of the containing triangle / tetrahedron; its
//                  metric is taken as is (piecewise constant field);
//   Element        A_t — all vertices of the containing triangle / tetrahedron;
//   Neighbourhood  A_o — "natural neighbourhood": all vertices of every triangle /
//                  tetrahedron whose circumcircle / circumsphere strictly contains the
//                  point (the containing element included).
// Default: Element (A_t), chosen by measurement (Release, shared 2-core machine):
//   accuracy — mean / max δ_M to the analytic field at 20000 random points after the
//   continuous adaptation with the same set (ε_δ = 0.2; 2D: the swirl field of test
//   MethodsAgainstAnalyticField; 3D: the twist field of the octree tests):
//     2D  A_s 0.063 / 0.84   A_t 0.018 / 0.26   A_o 0.020 / 0.35
//     3D  A_s 0.040 / 0.56   A_t 0.009 / 0.25   A_o 0.014 / 0.22
//   speed — getMetric() at random points of the bench_control_space meshes
//   (BM_Mesh2dQuery / BM_Mesh3dQuery, one thread, 20–35 k control vertices):
//     2D  A_s 5.5 M/s   A_t 2.6 M/s   A_o 0.75 M/s   (quadtree 15.7 M/s)
//     3D  A_s 3.2 M/s   A_t 2.4 M/s   A_o 0.23 M/s   (octree 8.7 M/s)
// A_t is as accurate as A_o (more, on average: the natural neighbourhood pulls in farther
// vertices whose weight is not negligible) and 3.5–10× faster; A_s is the fastest but
// only fit for nearly constant fields (the thesis says as much): its error is the jump
// between neighbouring vertices.
//
// Check points of the continuous adaptation: the thesis compares at the middle point of
// each element only (BackgroundCheck::Centroid). Inverse-distance weights
// are least accurate near the edges, where the third (fourth) vertex of an element still
// weighs in; checking the edge midpoints as well (CentroidEdges) catches that. Measured
// on AN1 (control_mesh_test): from the default grid, fraction of random points within
// ε_δ 0.987 → 0.997 (A_t); from a coarse grid 0.91 → 1.0 (9 → 49 control vertices); on
// the bench fields, mean δ_M to the source 0.061 → 0.034 (2D) and 0.046 → 0.022 (3D)
// with 1.5–1.7× the control vertices, so CentroidEdges is the default. (Continuous
// sources only; the parameterization
// adaptation checks the centroid.)
#include <cstddef>

#include "mesher/core/MeshOptions.h"

namespace aniso {

enum class BackgroundInterpolation {
  Single,         ///< A_s
  Element,        ///< A_t
  Neighbourhood,  ///< A_o
};

/// Where the continuous-source adaptation compares the interpolated metric with the
/// source (sec. 3.4.2).
enum class BackgroundCheck {
  Centroid,       ///< the thesis: the middle point of each element
  CentroidEdges,  ///< also the points halfway between the centroid and each edge midpoint
};

struct BackgroundMeshOptions {
  BackgroundInterpolation interpolation = BackgroundInterpolation::Element;
  BackgroundCheck check = BackgroundCheck::CentroidEdges;
  /// Points of the regular initial grid of a continuous source (sec. 3.4.2) along the
  /// longest side of the bounds; the other sides get as many as keep the cells near-square
  /// (at least 2 points per side).
  int initialGrid = 8;
  /// The continuous-source and parameterization adaptations do not refine an element
  /// whose edges are all shorter than this in metric units (in the metric of each of its
  /// vertices and of the check point): variation far below the element size does not
  /// affect a mesh, and a discontinuous source would otherwise be refined without end.
  /// Same meaning as TreeLimits::minLeafMetricLength.
  double minElementMetricLength = 0.5;
  /// Budget of control vertices for the adaptations (continuous source, parameterization,
  /// rings of point sources): beyond it they stop refining (the field stays valid, only
  /// less accurate). Guards against runaway refinement of pathological sources.
  std::size_t maxVertices = 4'000'000;
  /// Rounds of ring insertion around an updating point source (see CSMesh2d.h).
  int maxRingRounds = 8;
  /// Margin of the kernel's enclosing box around the bounds (Triangulation2dOptions /
  /// createEnclosingBox), relative to the largest side.
  double boxMargin = 0.1;
};

/// Throws InputError for ε_M < 0, ε_δ ≤ 0, l_Mmax ≤ 0 (as the quadtree) or bad options
/// (initialGrid < 2, minElementMetricLength < 0, maxVertices < 16, maxRingRounds < 0,
/// boxMargin ≤ 0, anything not finite).
void checkBackgroundParameters(const SizingParameters& params, const BackgroundMeshOptions& options);

}  // namespace aniso
