#pragma once
// Gaps of a face's discretized boundary (thesis sec. 3.5.1, "vicinity of boundaries"):
// places where two boundary segments that are not neighbours along the boundary come
// closer than 1/l_Mmax in the face's metric — a thin strip, a narrow gap between a hole
// and the outer loop, a sharp corner. The thesis finds them from the heights of the
// boundary triangulation; here they are found segment to segment with a bucket grid in
// (u, v), distances taken from each segment's midpoint in S^R with M_p at the midpoint
// (locally exact, so the same criterion).
//
// Two segments of one loop are "the same side" (no gap) when the loop joins them by a path
// not much longer than the straight distance: a gap needs the boundary to go away and come
// back (path > kGapPathRatio × distance; corners sharper than about 37° count as gaps).
//
// Also the width of the face as its boundary sees it (thinFaceWidth), which decides the
// face's own h_min (FaceMinSize in BoundaryUpdate.h).
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/surface/FaceBoundary.h"

namespace aniso {

struct BoundarySegment {
  Vec2 a, b;         ///< ends in (u, v)
  int loop = 0;      ///< loop index in the FaceBoundary
  double along = 0;  ///< real length along the loop from its first node to the midpoint
  double length = 0; ///< real length (in S^R, M_p at the midpoint)
};

struct BoundarySegments {
  std::vector<BoundarySegment> segments;  ///< pole pieces (same node at both ends) left out
  std::vector<double> loopLength;         ///< real length of each loop
  std::vector<int> loopFirst;             ///< each loop's first segment, then segments.size()
  Box2 box;                               ///< (u, v) box of every boundary node
};

/// The segments of the face's loops, lengths measured with the control space's M_p.
BoundarySegments boundarySegments(const ControlSpace2d& cs, const FaceBoundary& boundary);

struct BoundaryGap {
  int segment = -1;  ///< the segment whose midpoint is close to ...
  int other = -1;    ///< ... this segment (another side of the gap)
  Vec2 at;           ///< the nearest point of `other`, in (u, v)
  Vec2 across;       ///< from the midpoint of `segment` to `at`, in S^R (real vector)
  double metricWidth = 0;  ///< |M (at − midpoint)|, in the face's metric at the midpoint
  double width() const { return across.norm(); }
};

/// For every segment, the nearest segment (in the metric) of another side closer than lMin
/// in the metric or than minWidth in space (at most one gap per segment, in segment order).
/// minWidth makes the answer independent of how far the control space is already refined
/// (thinFaceWidth must see a thin face's gaps in every round). Deterministic.
std::vector<BoundaryGap> findBoundaryGaps(const ControlSpace2d& cs, const BoundarySegments& segs, double lMin,
                                          double minWidth);

/// The face's width as its boundary sees it: the length-weighted mean over the segments of
/// min(gap width, cap), a segment with no gap counting as cap. A strip of width w and length
/// L ≫ w gives about w; a face with only a thin tip or a narrow neck gives about cap.
/// Returns cap when there are no segments.
double thinFaceWidth(const BoundarySegments& segs, const std::vector<BoundaryGap>& gaps, double cap);

/// The segments that cross another segment of the face's loops, or touch its interior with
/// an end, other than at a shared end (exact orientation tests): a boundary whose polygons
/// cross in (u, v) cannot be triangulated (two CAD edges a few micrometres apart, each
/// discretized by its own chords deviating by more than the gap; docs/measurements.md).
/// Ascending, each once. Deterministic.
std::vector<int> crossingSegments(const BoundarySegments& segs);

}  // namespace aniso
