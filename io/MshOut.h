#pragma once
// Token output shared by the MSH writers: ASCII numbers separated by spaces, or raw
// native-endian binary values, as the MSH formats ask for each section.
#include <algorithm>
#include <iomanip>
#include <ostream>
#include <string>
#include <vector>

#include "io/OutputMesh.h"

namespace aniso::io {

class MshOut {
 public:
  MshOut(std::ostream& o, bool binary) : o_(o), binary_(binary) { o_ << std::setprecision(17); }
  template <class T>
  void value(T v, char sep = ' ') {
    if (binary_) {
      o_.write(reinterpret_cast<const char*>(&v), sizeof(T));
    } else {
      o_ << v << sep;
    }
  }
  void endLine() {
    if (!binary_) o_ << '\n';
  }
  /// Before an $End... line: binary data ends without a newline.
  void endSection(const char* tag) { o_ << (binary_ ? "\n" : "") << tag << '\n'; }
  bool binary() const { return binary_; }

 private:
  std::ostream& o_;
  bool binary_;
};

/// $MeshFormat of `version` ("4.1" or "2.2"), ASCII or binary (with the endianness check),
/// then $PhysicalNames: "FACE<n>" (dim 2, tag n) for every meshed face, the solid's group
/// name (dim 3, tag = solid id, solidGroupNames) for every meshed solid. Names are quoted:
/// a '"' in a name becomes '_'.
inline void writeMshHeader(std::ostream& o, const char* version, bool binary, const OutputMesh& m) {
  o << "$MeshFormat\n" << version << ' ' << (binary ? 1 : 0) << " 8\n";
  if (binary) {
    const int one = 1;
    o.write(reinterpret_cast<const char*>(&one), sizeof one);
    o << '\n';
  }
  o << "$EndMeshFormat\n";
  const std::vector<bool> faces = m.meshedFaces(), solids = m.meshedSolids();
  const std::vector<std::string> solidNames = solidGroupNames(m.model);
  const auto n = std::count(faces.begin(), faces.end(), true) + std::count(solids.begin(), solids.end(), true);
  o << "$PhysicalNames\n" << n << '\n';
  for (size_t f = 0; f < faces.size(); ++f)
    if (faces[f]) o << "2 " << f + 1 << " \"FACE" << f + 1 << "\"\n";
  for (size_t s = 0; s < solids.size(); ++s) {
    if (!solids[s]) continue;
    std::string name = solidNames[s];
    std::replace(name.begin(), name.end(), '"', '_');
    o << "3 " << s + 1 << " \"" << name << "\"\n";
  }
  o << "$EndPhysicalNames\n";
}

}  // namespace aniso::io
