#pragma once
// Token output shared by the MSH writers: ASCII numbers separated by spaces, or raw
// native-endian binary values, as the MSH formats ask for each section.
// ASCII numbers are formatted by std::to_chars: integers in decimal, doubles as printf's
// "%.17g" (to_chars with chars_format::general and precision 17 is specified as exactly
// that; the same text as an ostream at setprecision(17)), so every double reads back to
// the same value.
// Output is buffered (the stream sees it in blocks of about kFlushBytes): endSection()
// and flush() hand it to the stream — every section ends with endSection(), and a writer
// writes to the stream itself only when the buffer is empty (before the first value or
// after an endSection()); text() writes through the buffer.
#include <algorithm>
#include <charconv>
#include <cstring>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "io/OutputMesh.h"

namespace aniso::io {

class MshOut {
 public:
  /// Buffered bytes that trigger a write to the stream at the end of a line.
  static constexpr std::size_t kFlushBytes = std::size_t{1} << 16;

  MshOut(std::ostream& o, bool binary) : o_(o), binary_(binary) { buf_.reserve(kFlushBytes + 512); }
  template <class T>
  void value(T v, char sep = ' ') {
    static_assert(std::is_arithmetic_v<T>);
    if (binary_) {
      buf_.append(reinterpret_cast<const char*>(&v), sizeof(T));
      return;
    }
    ascii(v);
    buf_.push_back(sep);
  }
  /// An ASCII number and a newline in either mode (the counts after the MSH 2.2 headers).
  template <class T>
  void asciiLine(T v) {
    ascii(v);
    buf_.push_back('\n');
  }
  void endLine() {
    if (!binary_) buf_.push_back('\n');
    if (buf_.size() >= kFlushBytes) flush();
  }
  /// Text as it is (section headers in either mode).
  void text(std::string_view s) { buf_.append(s); }
  /// Before an $End... line: binary data ends without a newline. Flushes.
  void endSection(const char* tag) {
    if (binary_) buf_.push_back('\n');
    buf_.append(tag);
    buf_.push_back('\n');
    flush();
  }
  void flush() {
    o_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }
  bool binary() const { return binary_; }

 private:
  template <class T>
  void ascii(T v) {
    char tmp[40];
    std::to_chars_result r;
    if constexpr (std::is_floating_point_v<T>) {
      r = std::to_chars(tmp, tmp + sizeof tmp, v, std::chars_format::general, 17);
    } else {
      r = std::to_chars(tmp, tmp + sizeof tmp, v);
    }
    buf_.append(tmp, static_cast<std::size_t>(r.ptr - tmp));
  }

  std::ostream& o_;
  bool binary_;
  std::string buf_;
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
