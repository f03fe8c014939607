#pragma once
// The run report's content from meshModel's result (mesher/pipeline/MeshResult.h): counts,
// quality of the surface (per face) and of the volume (VolumeReport.h), the element budget
// (BudgetReport.h), the proximity rounds, the coarse-solid retry, order 2, the stages'
// decisions ("stages") and every problem. The caller adds input, options, times of its own
// phases and the status.
#include "io/Report.h"
#include "mesher/model/Model.h"
#include "mesher/pipeline/MeshResult.h"
#include "tools/app/MeshArgs.h"

namespace aniso::app {

/// The report's "options": the arguments as given (dim and anisotropy before resolution).
nlohmann::ordered_json optionsJson(const MeshArgs& args);

void fillRunReport(const Model& model, const MeshResult& result, io::Report& report);

}  // namespace aniso::app
