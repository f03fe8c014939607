#pragma once
// MeshRequest — what a program asks meshModel (Pipeline.h) for: the options (sizing, dim,
// order, quad, threads, element budget, cancellation) and the user's sizing. The caller
// resolves what depends on the machine (the default element budget) and on its own
// conventions (the default anisotropy of a volume mesh) before the call.
#include "mesher/control/ControlSpace2d.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/sizing/UserSizing.h"

namespace aniso {

struct MeshRequest {
  /// The program's defaults (the sizing of SizingParameters::forAnalysis(), as the CLI);
  /// options.dim 0: 3 when the model has solids, else 2.
  MeshOptions options = programDefaults();
  UserSizing user;      ///< the user's 3D sources (--sizing); empty: none
  /// The 2D sizing of a single-face analytic model over its (u, v) domain; null: none.
  /// Not owned; must outlive the call.
  const ControlSpace2d* analytic = nullptr;

  static MeshOptions programDefaults() {
    MeshOptions o;
    o.sizing = SizingParameters::forAnalysis();
    return o;
  }
};

/// The dimension a request meshes in: options.dim, or 3 when it is 0 and the model has solids.
int resolvedDim(const MeshOptions& options, bool modelHasSolids);

}  // namespace aniso
