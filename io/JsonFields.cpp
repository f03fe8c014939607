#include "io/JsonFields.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "mesher/core/Error.h"

namespace aniso::io {

JsonFields::json JsonFields::parseObject(const std::string& what) const {
  if (!std::filesystem::exists(path_)) fail("no such " + what);
  if (!std::filesystem::is_regular_file(path_)) fail("the " + what + " is not a regular file");
  std::ifstream in(path_);
  if (!in) fail("the " + what + " cannot be opened for reading");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception& e) {
    fail("not a valid JSON " + what + ": " + e.what());
  }
  if (!j.is_object()) fail("a " + what + " must be a JSON object");
  return j;
}

void JsonFields::fail(const std::string& what) const { throw InputError(path_ + ": " + what); }

const JsonFields::json& JsonFields::field(const json& j, const char* key, const std::string& where) const {
  if (!j.is_object() || !j.contains(key)) fail(where + " has no \"" + key + "\"");
  return j.at(key);
}

double JsonFields::number(const json& j, const std::string& where) const {
  if (!j.is_number() || !std::isfinite(j.get<double>())) fail(where + " must be a finite number");
  return j.get<double>();
}

Vec2 JsonFields::vec2(const json& j, const std::string& where) const {
  if (!j.is_array() || j.size() != 2) fail(where + " must be [a, b]");
  return {number(j[0], where), number(j[1], where)};
}

Vec3 JsonFields::vec3(const json& j, const std::string& where) const {
  if (!j.is_array() || j.size() != 3) fail(where + " must be [x, y, z]");
  return {number(j[0], where), number(j[1], where), number(j[2], where)};
}

std::string JsonFields::expression(const json& j, const std::string& where) const {
  if (j.is_number()) return j.dump();
  if (!j.is_string() || j.get<std::string>().empty()) fail(where + " must be an expression string");
  return j.get<std::string>();
}

}  // namespace aniso::io
