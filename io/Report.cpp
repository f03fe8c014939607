#include "io/Report.h"

namespace aniso::io {

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
  nlohmann::ordered_json f = nlohmann::ordered_json::array(), all = nlohmann::ordered_json::array();
  for (const Problem& p : problems) {
    if (p.severity == Severity::Failed) f.push_back({{"entity", entityName(p.entity)}, {"what", p.detail}});
    nlohmann::ordered_json q = {{"entity", entityName(p.entity)},
                                {"kind", entityKindName(p.entity.kind)},
                                {"id", p.entity.id},
                                {"severity", severityName(p.severity)},
                                {"code", p.code},
                                {"detail", p.detail},
                                {"phase", p.where}};
    if (!p.entity.part.empty()) q["part"] = p.entity.part;
    all.push_back(std::move(q));
  }
  j["failures"] = f;
  j["problems"] = all;
  for (const auto& [k, v] : extra.items()) j[k] = v;
  return j;
}

}  // namespace aniso::io
