#pragma once
// The element-size options of the mesh and sizing commands (README, "Element size"):
// their definitions, in the help group "Element size", and the checks that refuse
// conflicting ones with exit 2 and one sentence naming the fix.
#include <CLI/CLI.hpp>

#include <optional>

#include "mesher/core/MeshOptions.h"

namespace aniso::cli {

/// The help group of the size options (with the unit).
inline constexpr const char* kSizeGroup =
    "Element size (lengths in model units: mm for STEP and IGES, the file's unit for BREP)";

/// The size options of one command, bound to `params` (whose values are the defaults
/// shown). After parsing, resolve() checks them and folds --elements-per-circle and
/// --no-curvature into `params`. The object must outlive the parse.
class SizeOptions {
 public:
  /// volumeIsotropic: the command makes its meshes isotropic unless --anisotropy is
  /// given (mesh), which the help of --anisotropy says.
  SizeOptions(CLI::App& cmd, SizingParameters& params, bool volumeIsotropic);
  /// Throws InputError on conflicting or invalid options (e.g. --size with --hmax, --hmin
  /// above --hmax, both --elements-per-circle and --curvature-ratio).
  void resolve();

 private:
  bool given(const char* name) const;
  CLI::App& cmd_;
  SizingParameters& params_;
  std::optional<double> elementsPerCircle_;
  bool noCurvature_ = false;
};

}  // namespace aniso::cli
