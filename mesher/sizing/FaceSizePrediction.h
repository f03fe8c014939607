#pragma once
// The number of triangles a face's control space asks for, before meshing (thesis 6.5,
// eq. 6.2 applied to the control space instead of the initial triangulation).
//
// NT_f = Σ |det(M_s M_p)| a / S_M(K_I): the metric area of the face over that of the ideal
// (unit equilateral) triangle, summed over kSamplesPerAxis² points of every leaf of the
// quadtree that lie inside the face's discretized boundary (the winding number of its (u, v)
// loops is not 0), a being the sample's share of the leaf's (u, v) area. det M_s = 1/(h_1 h_2);
// the lengths are kept per sample, so that the count with a floor h_c on every length
// (h_i ← max(h_i, h_c), what coarsening does) costs no control-space query.
// Cost: O(samples · boundary segments / rows) with the segments bucketed by v rows.
#include <vector>

#include "mesher/control/CSQuadtree2d.h"
#include "mesher/surface/FaceBoundary.h"

namespace aniso {

/// Samples per leaf and axis.
inline constexpr int kSamplesPerAxis = 2;

/// The sized samples of one face inside its boundary.
class FaceSizePrediction {
 public:
  FaceSizePrediction() = default;
  /// Samples cs (initialized, parameterization adapted) over the face bounded by `boundary`.
  FaceSizePrediction(const CSQuadtree2d& cs, const FaceBoundary& boundary);

  /// Predicted triangles with every length raised to at least hFloor (0: as asked).
  double triangles(double hFloor = 0) const;
  /// The face's area inside its boundary (the samples' weights: det M_p is the area element).
  double area() const;
  /// The smallest length asked anywhere in the face (+inf without samples).
  double smallestLength() const { return smallest_; }

 private:
  struct Sample {
    double h1, h2;   ///< sizing lengths
    double weight;   ///< (u, v) area × det M_p
  };
  std::vector<Sample> samples_;
  double smallest_ = 0;
};

/// Raises every length of every control vertex of cs to at least hFloor (directions kept).
/// Raising from below never steepens a gradation. Returns the vertices changed.
int applySizeFloor(CSAdaptive2d& cs, double hFloor);

}  // namespace aniso
