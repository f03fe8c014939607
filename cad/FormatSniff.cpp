#include "cad/FormatSniff.h"

#include <algorithm>
#include <cctype>

#include "mesher/core/FileExtension.h"

namespace aniso::cad {

std::optional<CadFormat> formatFromExtension(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".step" || ext == ".stp") return CadFormat::Step;
  if (ext == ".igs" || ext == ".iges") return CadFormat::Iges;
  if (ext == ".brep" || ext == ".brp") return CadFormat::Brep;
  return std::nullopt;
}

std::optional<CadFormat> formatFromContent(const std::string& head) {
  // Skip a UTF-8 byte order mark, leading blank space and (STEP, ISO 10303-21 allows them
  // anywhere) /* comments */ before the first keyword.
  size_t i = 0;
  if (head.compare(0, 3, "\xEF\xBB\xBF") == 0) i = 3;
  for (;;) {
    while (i < head.size() && std::isspace(static_cast<unsigned char>(head[i]))) ++i;
    if (head.compare(i, 2, "/*") != 0) break;
    const size_t end = head.find("*/", i + 2);
    if (end == std::string::npos) break;
    i = end + 2;
  }
  const std::string s = head.substr(i);
  if (s.rfind("ISO-10303-21", 0) == 0) return CadFormat::Step;
  if (s.rfind("DBRep_DrawableShape", 0) == 0 || s.rfind("CASCADE Topology", 0) == 0)
    return CadFormat::Brep;
  // IGES: the first record is 80 columns with the section letter 'S' (start) or 'G'
  // (global, when the start section is empty) in column 73 and a sequence number after it.
  const size_t eol = head.find_first_of("\r\n");
  const std::string first = head.substr(0, eol);
  if (first.size() >= 73 && first.size() <= 82 && (first[72] == 'S' || first[72] == 'G')) {
    const std::string seq = first.substr(73);
    bool digits = !seq.empty() &&
                  std::all_of(seq.begin(), seq.end(), [](unsigned char c) { return std::isdigit(c) || c == ' '; });
    if (digits) return CadFormat::Iges;
  }
  return std::nullopt;
}

}  // namespace aniso::cad
