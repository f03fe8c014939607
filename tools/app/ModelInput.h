#pragma once
// Loading what the mesh and sizing commands work on: a CAD file (read, prepared, turned
// into the mesher's topology) or a .json analytic model. Bad input throws InputError.
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cad/CadModel.h"
#include "io/AnalyticModel.h"
#include "mesher/control/ControlSpace2d.h"
#include "mesher/core/Cancel.h"
#include "mesher/core/Problem.h"
#include "mesher/model/Model.h"

namespace aniso::app {

struct ModelInput {
  Model model;
  int solids = 0;
  bool analytic = false;
  std::optional<io::AnalyticSizing> analyticSizing;  ///< analytic models only
  nlohmann::ordered_json summary;                    ///< for the report's "model"
  std::vector<std::pair<std::string, double>> times; ///< read, prepare, topology
  /// Shortcomings of the preparation, graded (a solid left unfragmented: degraded).
  std::vector<Problem> problems;
};

/// Reads and prepares `file` (fragmenting the solids if `fragment`, overlapping ones by
/// `overlaps`); the preparation's warnings are logged. `cancel` (--time-limit) stops reading
/// and preparing too (cad::CadModel).
ModelInput loadModel(const std::string& file, bool fragment,
                     cad::OverlapPolicy overlaps = cad::OverlapPolicy::Merge, const CancelToken* cancel = nullptr);

/// The analytic sizing of an analytic model as a control space over its (u, v) domain.
std::unique_ptr<ControlSpace2d> analyticControlSpace(const ModelInput& in);

}  // namespace aniso::app
