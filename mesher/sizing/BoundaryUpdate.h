#pragma once
// Updating a face's control space from its discretized boundary (thesis alg. 3.1 lines
// 7 and 10, sec. 3.5.1 "Updating control space"):
//   - length of boundary segments: a segment shorter than 1/l_Mmax in the face's metric
//     (the edge was discretized finer for a neighbouring face) inserts a source of the
//     segment's length there, so the face's elements grade smoothly from the finer edge
//     (the cross-patch update of fig. 3.8);
//   - vicinity of boundaries (BoundaryGaps.h): where two boundary segments of different
//     sides are closer than 1/l_Mmax in the metric (a thin strip, a narrow gap, a sharp
//     corner), sources ask for elements no longer than the gap across it (and at most γ_a
//     times that along it), so that no triangle spans the gap: at the segment's midpoint
//     and at the nearest point of the other side with the gap found there, and at the
//     segment's ends with their distance to that other segment (a tapering gap is
//     narrower at one end).
//     Applied always to thin faces (below) and to strips — faces with more than
//     stripFraction of their boundary length across a gap: a fillet, a trailing-edge band
//     —, to the other faces only with options.vicinity. On every face the rule resolves
//     wedges between tangent CAD edges and sharp corners into many mediocre elements and
//     lowers the mean ratio; on strips and thin faces only, it removes most of the needles
//     the CAD does not force (tools/bench/surface_small_features.py; docs/measurements.md).
//
//   - crossing boundary (crossingSegments, BoundaryGaps.h): segments whose chords cross
//     another side in (u, v) (two CAD edges closer than their chords' deviation) ask for
//     half their length at their ends and midpoint (never below h_min), so that the next
//     round's chords follow their curves closer; after the rounds a boundary still crossing
//     fails the face as before. A face whose boundary does not cross gets no such source.
//
// The face's own h_min (faceMinSize): sizes never go below h_min, except on a thin face —
// one whose boundary width (thinFaceWidth, BoundaryGaps.h, the mean over the boundary of
// the gap widths capped at h_min) is below thinFaceWidth · h_min, like a strip narrower
// than h_min along its length. Such a face gets h_min_f = its width, bounded below by
// thinFaceRatio · h_min and by kToleranceFactor × its CAD tolerance (never above h_min),
// so that it meshes in well-shaped elements of its own width instead of needles h_min
// long; faces that are only locally thin (a tapering tip, a neck) keep h_min.
// In a volume mesh (thinFaces false) no face gets its own h_min: a face narrower than h_min
// inside a solid is a step or a sliver face of the CAD (a planar rim micrometres wide and
// tens of millimetres long between two faces), and its width carried into the neighbouring
// faces and the volume fills the solid around it with tiny, poor tets. Left at h_min its
// long edges take the neighbours' sizes, its triangles are caps well below the local size,
// and the surface repair removes them (SurfaceSlivers.h, kLocalSliverRatio;
// docs/measurements.md).
// Gaps narrower than resolvedGapRatio · h_min (on a thin face: half its h_min_f) get no
// source: elements of the smallest size cannot span them well, and refining there only
// multiplies the needles — at the tip of two CAD edges meeting at a tiny angle the gap
// sources would carry the smallest size into the tip (docs/measurements.md). Left
// coarse, the tip keeps few. Short-segment sources are bounded below by h_min_f too (a CAD
// edge shorter than h_min_f does not drive the neighbourhood to round-off); in a volume
// mesh, a strip narrower than resolvedGapRatio · h_min (its gaps get no source; a step or
// sliver face of the CAD like the rim above) gets none for its segments shorter than that,
// its ends: those sources graded h_min into the faces around, and the steps were meshed in
// needles with flat tets around them. Left coarse, the surface repair merges the step away.
// A strip between two faces facing opposite ways is the rim of a film, not a step: nothing
// merges it, and its ends keep their sources (without them the mean ratio dropped). Short
// segments of other faces keep their sources: skins narrower than h_min only towards a
// sharp trailing edge came out with slivers without them (docs/measurements.md).
#include "mesher/control/CSAdaptive2d.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/surface/FaceBoundary.h"

namespace aniso {

struct BoundaryUpdateStats {
  int shortSegments = 0;   ///< sources from segments too short for the face's metric
  int gaps = 0;            ///< sources from boundary vicinity
  int unresolvedGaps = 0;  ///< gaps too narrow to resolve (no source)
  int crossings = 0;       ///< segments crossing another one, given half their length
  int stepEnds = 0;        ///< short segments of a step face, given no source (volume meshes)
  double faceMinSize = 0;  ///< h_min_f used
  int total() const { return shortSegments + gaps + crossings; }
};

struct BoundaryUpdateOptions {
  double hMin = 0;          ///< the model's h_min (lower bound of the requested sizes)
  bool vicinity = false;    ///< the vicinity rule on every face (thin faces and strips always get it)
  double stripFraction = 0.6;  ///< a face with more of its boundary length across a gap is a strip
  bool thinFaces = true;          ///< thin faces get their own h_min (false: volume meshes, above)
  /// The face is the rim of a film (EdgeNormals.h, filmRims): never a step (above).
  bool filmRim = false;
  /// Gap sources all along a segment much longer than the gap (BoundaryUpdate.cpp,
  /// kGapSourceSpacing; false: volume meshes).
  bool gapsAlongSegments = true;
  double thinFaceWidth = 0.5;     ///< a face narrower than this × h_min is thin
  double thinFaceRatio = 0.1;     ///< lowest h_min_f, relative to h_min
  double cadTolerance = 0;        ///< the face's CAD tolerance (model units)
  double resolvedGapRatio = 2.0;  ///< narrower gaps (relative to h_min) get no source, thin faces aside
  /// Only the crossing rule (the rounds after alg. 3.1's: a boundary the last round's
  /// sources made cross, since the sides of a gap are refined unequally).
  bool crossingsOnly = false;
};

/// h_min_f of the rules above for a face whose boundary width is `width`.
double faceMinSize(double width, const BoundaryUpdateOptions& options);

/// Inserts the sources described above into `cs` (initialized). Returns what it did.
BoundaryUpdateStats updateFromBoundary(CSAdaptive2d& cs, const FaceBoundary& boundary,
                                       const SizingParameters& params, const BoundaryUpdateOptions& options);

}  // namespace aniso
