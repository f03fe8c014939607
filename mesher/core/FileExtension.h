#pragma once
// The extension of a path in lower case (".step" for "Part.STEP", "" for none): how every
// reader and writer chooses by extension, in one place; and a word in lower case (ASCII).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace aniso {

inline std::string lowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

inline std::string lowerExtension(const std::string& path) {
  return lowerCase(std::filesystem::path(path).extension().string());
}

}  // namespace aniso
