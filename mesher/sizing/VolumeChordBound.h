#pragma once
// volumeChordDeviation — the chord deviation that keeps the meshed volume of a model.
//
// The model-wide chord bound δ (SizingParameters::chordDeviationRel × diagonal) keeps a
// large part's curved faces close, but leaves a small part's 12 chords per circle: a screw,
// a nut, a wing section loses more than a percent of its volume. A chord of sagitta δ over
// a curved face of area A_f moves about (2/3) δ A_f of volume, out of the solid where the
// face bulges out (convex), into it where it bulges in (a hole, a fillet inside a corner):
// solids of volume V whose convex curved faces exceed their concave ones by the area B
// (summed over the solids, each solid's excess taken positive) keep their volume within
// about (2/3) δ B / V when
//     δ ≤ kVolumeChordRatio × V / B.
// Convexity is sampled on a grid of each face's parametric box. One δ for the whole model:
// the total volume is what a solver's mass and a reviewer's check see, and a small part of
// an assembly does not refine the rest (a per-solid bound multiplied an assembly's tets for
// nothing the checks see: docs/census.md, session 14). A thin curved wall is bounded by its
// radius, not its thickness (its two sides cancel but for their difference in area); models
// whose curved faces are a small part of their volume keep δ. δ = 0 (the thesis' sizing)
// stays 0; a model with an unknown CAD volume or face area, or no solid, keeps δ.
#include "mesher/model/Model.h"

namespace aniso {

/// δ over V / B (see above): (2/3) × 0.005 ≈ 0.33 % by the estimate; meshes lose up to
/// about twice that (edges up to √2 times their size, sagitta ∝ length²): wing_fuselage
/// −1.08 % at 0.01 with convexity taken at the face centre only (−0.34 % at 0.005 with
/// the grid), −1.29 % at the model-wide δ alone.
inline constexpr double kVolumeChordRatio = 0.005;

/// The chord deviation (absolute) for `model`, given the model-wide one `chord` (≥ 0).
/// Evaluates 25 curvatures per curved face: computed once per run (SurfaceMesherInput).
double volumeChordDeviation(const Model& model, double chord);

}  // namespace aniso
