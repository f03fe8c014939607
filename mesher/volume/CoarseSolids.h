#pragma once
// coarseSolidSources — the quality side of alg. 3.3's outer loop (thesis 3.5.2: the volume
// sends faces back to the surface mesher when they are too coarse for it). The proximity
// loop (ThinBoundary.h) catches solids thinner than their triangles; a solid whose surface
// is so coarse that its faces have one or two triangles per side is not thin, yet no
// tetrahedralisation of that surface reaches the quality bar: two unit cubes sharing a face
// at the defaults (h = 1.22) get square faces of two right triangles each, and the best
// fill, a point at each cube's centre, has mean ratio 0.762 (four triangles per face, as
// box.brep gets, allow 0.905). For every solid whose tets' referee mean ratio is below
// kCoarseMeanRatio and whose surface is coarse — at most kCoarseTrianglesPerFace triangles
// per face on average (a solid meshed finely but still poor, like thin skins, is the
// proximity loop's: refined here its boxes doubled the whole mesh; docs/measurements.md) —,
// a box source over its boundary (grown by the mean edge length L of its
// boundary triangles) asks for the isotropic size kCoarseRefine · L on the solid's own
// faces (SizingSource::faces: its neighbours in the box keep theirs); the caller meshes the
// surface and the volumes again once and keeps the result with the better mean ratio.
//
// failedSolidSources — a solid the volume mesher failed on (boundary not recovered: a
// surface too coarse where the part is thin or curved, its chords crossing, e.g. a helical
// wire at the defaults) gets the same box over its own faces at kFailedRefine · L; the
// proximity rounds (pipeline/VolumeStages.h) mesh it again with them, within their budget.
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/sizing/UserSizing.h"
#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/VolumeMesher.h"

namespace aniso {

/// A solid whose tets' mean ratio (Euclidean η, the referee's) is below this is coarse.
inline constexpr double kCoarseMeanRatio = 0.80;
/// Coarse: at most this many boundary triangles per face of the solid, on average.
inline constexpr double kCoarseTrianglesPerFace = 16;
/// Its surface is asked for this times its mean boundary edge length.
inline constexpr double kCoarseRefine = 0.6;

/// A failed solid's surface is asked for this times its mean boundary edge length.
inline constexpr double kFailedRefine = 0.5;

/// One box source per coarse solid of `solids` (indexed as model.solids); empty when none.
std::vector<SizingSource> coarseSolidSources(const Model& model, const SurfaceMesh& surface,
                                             const std::vector<SolidOutcome>& solids);

/// The (0-based) solids whose volume mesh failed, not left out for an unmeshed face.
std::vector<int> failedSolids(const std::vector<SolidOutcome>& solids);

/// One box source per solid of `solids` whose volume mesh failed (not left out for an
/// unmeshed face); empty when none.
std::vector<SizingSource> failedSolidSources(const Model& model, const SurfaceMesh& surface,
                                             const std::vector<SolidOutcome>& solids);

}  // namespace aniso
