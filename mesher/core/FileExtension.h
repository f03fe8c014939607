#pragma once
// The extension of a path in lower case (".step" for "Part.STEP", "" for none): how every
// reader and writer chooses by extension, in one place.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace aniso {

inline std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace aniso
