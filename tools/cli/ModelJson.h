#pragma once
// JSON and text forms of a CAD model's summary, shared by `info` and the mesh report.
#include <nlohmann/json.hpp>

#include <string>

#include "cad/CadModel.h"

namespace aniso::cli {

/// {"solids","shells","faces","edges","vertices","volume","area","bbox":{...},"solid_list":[...]}
nlohmann::ordered_json summaryJson(const cad::ShapeSummary& s);
/// {"sewn_faces","shared_faces","overlapping_solids":[[i,j]],"warnings":[...]}
nlohmann::ordered_json prepareJson(const cad::PrepareReport& r);
/// Human-readable lines.
std::string summaryText(const cad::ShapeSummary& s, const std::string& indent);

}  // namespace aniso::cli
