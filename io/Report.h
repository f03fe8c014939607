#pragma once
// The run report (--report FILE.json):
// {"status": "ok"|"degraded"|"failed", "input", "options",
//  "counts": {"nodes", "triangles", "quads", "tetrahedra"},
//  "times": {"total", <one entry per phase>}, "quality": {...},
//  "failures": [{"entity": "face 12", "what": ...}],          the problems of severity failed
//  "problems": [{"entity", "kind", "id", "part", "severity", "code", "detail", "phase"}], all of them
//  ...further sections (model, surface, proximity, ...)}
// The status follows mesher/core/Problem.h's grading policy.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "mesher/core/Problem.h"

namespace aniso::io {

using aniso::RunStatus;
using aniso::statusName;

struct Report {
  RunStatus status = RunStatus::Failed;
  std::string input;
  nlohmann::ordered_json options = nlohmann::ordered_json::object();
  long long nodes = 0, triangles = 0, quads = 0, tetrahedra = 0;
  /// Phase times in seconds, in the order the phases ran; "total" is added on output.
  std::vector<std::pair<std::string, double>> times;
  double totalSeconds = 0;
  nlohmann::ordered_json quality = nlohmann::ordered_json::object();
  std::vector<Problem> problems;
  /// Further sections (e.g. "model": the prepared model's summary, "warnings").
  nlohmann::ordered_json extra = nlohmann::ordered_json::object();

  nlohmann::ordered_json toJson() const;
};

}  // namespace aniso::io
