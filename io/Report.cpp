#include "io/Report.h"

namespace aniso::io {

const char* statusName(RunStatus s) {
  switch (s) {
    case RunStatus::Ok: return "ok";
    case RunStatus::Degraded: return "degraded";
    case RunStatus::Failed: return "failed";
  }
  return "failed";
}

nlohmann::ordered_json Report::toJson() const {
  nlohmann::ordered_json j;
  j["status"] = statusName(status);
  j["input"] = input;
  j["options"] = options;
  j["counts"] = {{"nodes", nodes}, {"triangles", triangles}, {"quads", quads}, {"tetrahedra", tetrahedra}};
  nlohmann::ordered_json t = nlohmann::ordered_json::object();
  t["total"] = totalSeconds;
  for (const auto& [phase, s] : times) t[phase] = s;
  j["times"] = t;
  j["quality"] = quality;
  nlohmann::ordered_json f = nlohmann::ordered_json::array();
  for (const Failure& x : failures) f.push_back({{"entity", x.entity}, {"what", x.what}});
  j["failures"] = f;
  for (const auto& [k, v] : extra.items()) j[k] = v;
  return j;
}

}  // namespace aniso::io
