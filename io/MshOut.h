#pragma once
// Token output shared by the MSH writers: ASCII numbers separated by spaces, or raw
// native-endian binary values, as the MSH formats ask for each section.
// ASCII numbers are formatted by std::to_chars: integers in decimal, doubles as printf's
// "%.17g" (to_chars with chars_format::general and precision 17 is specified as exactly
// that; the same text as an ostream at setprecision(17)), so every double reads back to
// the same value.
// Output is buffered in a fixed array (the stream sees it in blocks of about kFlushBytes):
// endSection() and flush() hand it to the stream — every section ends with endSection(),
// and a writer writes to the stream itself only when the buffer is empty (before the first
// value or after an endSection()); text() writes through the buffer.
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

  MshOut(std::ostream& o, bool binary) : o_(o), binary_(binary), buf_(kFlushBytes + kRoom) {}
  template <class T>
  void value(T v, char sep = ' ') {
    static_assert(std::is_arithmetic_v<T>);
    if (binary_) {
      std::memcpy(room(sizeof(T)), &v, sizeof(T));
      pos_ += sizeof(T);
      return;
    }
    ascii(v);
    buf_[pos_++] = sep;
  }
  /// An ASCII number and a newline in either mode (the counts after the MSH 2.2 headers).
  template <class T>
  void asciiLine(T v) {
    ascii(v);
    buf_[pos_++] = '\n';
  }
  void endLine() {
    if (!binary_) *room(1) = '\n', ++pos_;
    if (pos_ >= kFlushBytes) flush();
  }
  /// Text as it is (section headers in either mode).
  void text(std::string_view s) {
    if (s.size() > kRoom) {
      flush();
      o_.write(s.data(), static_cast<std::streamsize>(s.size()));
      return;
    }
    std::memcpy(room(s.size()), s.data(), s.size());
    pos_ += s.size();
  }
  /// Before an $End... line: binary data ends without a newline. Flushes.
  void endSection(const char* tag) {
    if (binary_) *room(1) = '\n', ++pos_;
    text(tag);
    *room(1) = '\n', ++pos_;
    flush();
  }
  void flush() {
    o_.write(buf_.data(), static_cast<std::streamsize>(pos_));
    pos_ = 0;
  }
  bool binary() const { return binary_; }

 private:
  /// Room for a number and its separator, or a section tag, at the end of the buffer.
  static constexpr std::size_t kRoom = 512;

  /// Where the next n ≤ kRoom bytes go (flushing first when the buffer lacks them).
  char* room(std::size_t n) {
    if (pos_ + n > buf_.size()) flush();
    return buf_.data() + pos_;
  }
  template <class T>
  void ascii(T v) {
    char* at = room(64);  // the longest number (25 characters) and its separator
    std::to_chars_result r;
    if constexpr (std::is_floating_point_v<T>) {
      r = std::to_chars(at, at + 63, v, std::chars_format::general, 17);
    } else {
      r = std::to_chars(at, at + 63, v);
    }
    pos_ += static_cast<std::size_t>(r.ptr - at);
  }

  std::ostream& o_;
  bool binary_;
  std::vector<char> buf_;
  std::size_t pos_ = 0;
};

/// The physical tag (dim 2) of face group k of groupNames(): after the FACE<n> tags 1..n.
inline int faceGroupTag(const Model& m, std::size_t k) { return static_cast<int>(m.faces.size() + k) + 1; }

/// True when face group g holds a meshed face.
inline bool groupMeshed(const FaceGroup& g, const std::vector<bool>& meshedFaces) {
  return std::any_of(g.faces.begin(), g.faces.end(), [&](int f) { return meshedFaces[static_cast<std::size_t>(f)]; });
}

/// $MeshFormat of `version` ("4.1" or "2.2"), ASCII or binary (with the endianness check),
/// then $PhysicalNames: "FACE<n>" (dim 2, tag n) for every meshed face, the solid's group
/// name (dim 3, tag = solid id, groupNames) for every meshed solid, then each named face
/// group with a meshed face (dim 2, faceGroupTag). Names are quoted (groupNames has no '"').
inline void writeMshHeader(std::ostream& o, const char* version, bool binary, const OutputMesh& m) {
  o << "$MeshFormat\n" << version << ' ' << (binary ? 1 : 0) << " 8\n";
  if (binary) {
    const int one = 1;
    o.write(reinterpret_cast<const char*>(&one), sizeof one);
    o << '\n';
  }
  o << "$EndMeshFormat\n";
  const std::vector<bool> faces = m.meshedFaces(), solids = m.meshedSolids();
  const GroupNames names = groupNames(m.model);
  const auto groups = std::count_if(names.faces.begin(), names.faces.end(),
                                    [&](const FaceGroup& g) { return groupMeshed(g, faces); });
  const auto n = std::count(faces.begin(), faces.end(), true) + std::count(solids.begin(), solids.end(), true) + groups;
  o << "$PhysicalNames\n" << n << '\n';
  for (size_t f = 0; f < faces.size(); ++f)
    if (faces[f]) o << "2 " << f + 1 << " \"FACE" << f + 1 << "\"\n";
  for (size_t s = 0; s < solids.size(); ++s)
    if (solids[s]) o << "3 " << s + 1 << " \"" << names.solids[s] << "\"\n";
  for (size_t k = 0; k < names.faces.size(); ++k)
    if (groupMeshed(names.faces[k], faces))
      o << "2 " << faceGroupTag(m.model, k) << " \"" << names.faces[k].name << "\"\n";
  o << "$EndPhysicalNames\n";
}

/// A $NodeData section (MSH 4.1 and 2.2 alike): one string tag (the quoted name, '"'
/// becoming '_'), one real tag (time 0), three integer tags (step 0, components, node
/// count), then per node its tag (index + 1; int32 in binary) and its values.
inline void writeMshNodeData(MshOut& w, const NodeData& d) {
  std::string name = d.name;
  std::replace(name.begin(), name.end(), '"', '_');
  const std::size_t n = d.values.size() / static_cast<std::size_t>(d.components);
  w.text("$NodeData\n1\n\"" + name + "\"\n1\n0\n3\n0\n" + std::to_string(d.components) + "\n" + std::to_string(n) + "\n");
  for (std::size_t i = 0; i < n; ++i) {
    w.value<int>(static_cast<int>(i) + 1);
    for (int c = 0; c < d.components; ++c) w.value<double>(d.values[i * d.components + c]);
    w.endLine();
  }
  w.endSection("$EndNodeData");
}

}  // namespace aniso::io
