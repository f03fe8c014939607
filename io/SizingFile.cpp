#include "io/SizingFile.h"
#include "io/JsonFields.h"

#include <nlohmann/json.hpp>

#include <cmath>

#include "mesher/core/Error.h"

namespace aniso::io {
namespace {

using nlohmann::json;

/// The sizing file's own field: "h" as a length or as lengths with directions.
struct Reader : JsonFields {
  using JsonFields::JsonFields;
  /// "h": a length or three lengths with optional "directions".
  Metric3d metric(const json& j, const std::string& where) const {
    const json& h = field(j, "h", where);
    if (h.is_number()) {
      const double v = number(h, where + ".h");
      if (v <= 0) fail(where + ".h must be positive");
      return Metric3d::isotropic(v);
    }
    const Vec3 l = vec3(h, where + ".h");
    if ((l.array() <= 0).any()) fail(where + ".h must be positive");
    Vec3 e[3] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
    if (j.contains("directions")) {
      const json& d = j["directions"];
      if (!d.is_array() || d.size() != 3) fail(where + ".directions must be three vectors");
      for (int i = 0; i < 3; ++i) {
        e[i] = vec3(d[i], where + ".directions");
        if (e[i].norm() == 0) fail(where + ".directions must be non-zero");
        e[i].normalize();
      }
      for (int i = 0; i < 3; ++i)
        if (std::abs(e[i].dot(e[(i + 1) % 3])) > 1e-6) fail(where + ".directions must be orthogonal");
    }
    return Metric3d::fromDirections(e[0], e[1], e[2], l[0], l[1], l[2]);
  }
};

}  // namespace

UserSizing readSizingFile(const std::string& path) {
  const Reader r(path);
  const json j = r.parseObject("sizing file");
  UserSizing out;
  if (j.contains("global")) out.global = r.metric(j["global"], "global");
  if (j.contains("sources")) {
    if (!j["sources"].is_array()) r.fail("sources must be an array");
    int k = 0;
    for (const json& s : j["sources"]) {
      const std::string where = "sources[" + std::to_string(k++) + "]";
      SizingSource src;
      const std::string type = s.value("type", "");
      if (type == "point") {
        src.kind = SizingSource::Kind::Point;
        src.a = r.vec3(r.field(s, "at", where), where + ".at");
      } else if (type == "segment") {
        src.kind = SizingSource::Kind::Segment;
        src.a = r.vec3(r.field(s, "from", where), where + ".from");
        src.b = r.vec3(r.field(s, "to", where), where + ".to");
      } else if (type == "box") {
        src.kind = SizingSource::Kind::Box;
        src.a = r.vec3(r.field(s, "min", where), where + ".min");
        src.b = r.vec3(r.field(s, "max", where), where + ".max");
        if ((src.a.array() > src.b.array()).any()) r.fail(where + ".min must not exceed .max");
      } else {
        r.fail(where + ".type must be \"point\", \"segment\" or \"box\"");
      }
      if (s.contains("radius")) {
        src.radius = r.number(s["radius"], where + ".radius");
        if (src.radius < 0) r.fail(where + ".radius must not be negative");
      }
      src.metric = r.metric(s, where);
      out.sources.push_back(src);
    }
  }
  if (!out.global && out.sources.empty()) r.fail("the sizing file defines no global size and no sources");
  return out;
}

}  // namespace aniso::io
