#pragma once
// JSON and text forms of a CAD model's summary, shared by `info` and the mesh report.
#include <nlohmann/json.hpp>

#include <string>

#include "cad/CadModel.h"

namespace aniso::app {

/// {"solids","shells","faces","edges","vertices","volume","area","bbox":{...},"solid_list":[...]}
nlohmann::ordered_json summaryJson(const cad::ShapeSummary& s);
/// {"sewn_faces","shared_faces","fuzzy","overlaps":[{"a","b","name_a","name_b","volume","assigned_to"}],
///  "warnings":[...]}; assigned_to is null when the common region stayed in both (--overlaps keep).
nlohmann::ordered_json prepareJson(const cad::PrepareReport& r);
/// Human-readable lines.
std::string summaryText(const cad::ShapeSummary& s, const std::string& indent);
/// One line per overlapping pair: ids, names, volume, the part that keeps the region.
std::string overlapsText(const cad::PrepareReport& r, const std::string& indent);

}  // namespace aniso::app
