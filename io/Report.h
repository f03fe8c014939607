#pragma once
// The run report (--report FILE.json), the contract of issue 2 §3:
// {"status": "ok"|"degraded"|"failed", "input", "options",
//  "counts": {"nodes", "triangles", "quads", "tetrahedra"},
//  "times": {"total", <one entry per phase>}, "quality": {...},
//  "failures": [{"entity": "face 12", "what": ...}]}
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace aniso::io {

enum class RunStatus { Ok, Degraded, Failed };
const char* statusName(RunStatus s);

struct Failure {
  std::string entity;  ///< "face 12", "edge 7", "solid 3", "model"
  std::string what;
};

struct Report {
  RunStatus status = RunStatus::Failed;
  std::string input;
  nlohmann::ordered_json options = nlohmann::ordered_json::object();
  long long nodes = 0, triangles = 0, quads = 0, tetrahedra = 0;
  /// Phase times in seconds, in the order the phases ran; "total" is added on output.
  std::vector<std::pair<std::string, double>> times;
  double totalSeconds = 0;
  nlohmann::ordered_json quality = nlohmann::ordered_json::object();
  std::vector<Failure> failures;
  /// Further sections (e.g. "model": the prepared model's summary, "warnings").
  nlohmann::ordered_json extra = nlohmann::ordered_json::object();

  nlohmann::ordered_json toJson() const;
};

}  // namespace aniso::io
