#pragma once
// Reading the project's small JSON input files (analytic models, sizing files) with checks:
// every problem becomes an InputError "<file>: <what>" naming the field.
#include <nlohmann/json.hpp>

#include <string>

#include "mesher/core/Types.h"

namespace aniso::io {

class JsonFields {
 public:
  using json = nlohmann::json;
  explicit JsonFields(const std::string& path) : path_(path) {}

  /// Opens and parses the file, which must hold a JSON object; `what` names the kind of
  /// file in the messages ("sizing file", "analytic model").
  json parseObject(const std::string& what) const;

  [[noreturn]] void fail(const std::string& what) const;
  /// j[key]; fails "<where> has no "<key>"" when j is not an object or lacks it.
  const json& field(const json& j, const char* key, const std::string& where) const;
  double number(const json& j, const std::string& where) const;  ///< finite number
  Vec2 vec2(const json& j, const std::string& where) const;       ///< [a, b]
  Vec3 vec3(const json& j, const std::string& where) const;       ///< [x, y, z]
  /// A non-empty expression string (a number is accepted and written as text).
  std::string expression(const json& j, const std::string& where) const;

 private:
  const std::string& path_;
};

}  // namespace aniso::io
