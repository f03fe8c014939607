#pragma once
// undoRefinementOfFailed — the proximity rounds' way back for one solid (VolumeStages.h):
// a solid whose volume fails on the finer surface of a round (its boundary not recovered;
// docs/measurements.md) loses the sources that size only its faces, so the next
// surface gives it back its earlier sizes while every other solid keeps its refinement
// (rather than the whole model falling back to the first surface).
#include <cstddef>
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/pipeline/MeshResult.h"
#include "mesher/sizing/UserSizing.h"

namespace aniso {

/// Removes from sizing.sources, after its first `userSources` (the user's, kept), every
/// source whose faces (SizingSource::faces, not empty) are all faces of the solids that
/// `solids` reports failed (failedSolids), keeping the others' order; removes those faces'
/// entries from px.refined and sets px.facesRefined to its size. Returns how many sources
/// were removed.
std::size_t undoRefinementOfFailed(const Model& model, std::size_t userSources, const std::vector<SolidOutcome>& solids,
                                   UserSizing& sizing, ProximityOutcome& px);

}  // namespace aniso
