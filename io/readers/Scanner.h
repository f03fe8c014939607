#pragma once
// Scanner — a cursor over a whole file held in memory, for the mesh readers: whitespace-
// separated tokens, numbers, lines and little-endian binary values (MSH mixes ASCII section
// headers with binary blocks). Every failure throws InputError naming the file and the
// line it happened on.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace aniso::io {

/// The whole file as bytes; InputError naming it when it cannot be read.
std::string readWholeFile(const std::string& path);

class Scanner {
 public:
  Scanner(std::string_view data, std::string file) : data_(data), file_(std::move(file)) {}

  bool atEnd() {
    skipSpace();
    return pos_ >= data_.size();
  }
  /// The next whitespace-separated token; fails at the end of the data.
  std::string_view token();
  long long integer();
  double real();
  /// The token must be `word`.
  void expect(std::string_view word);
  /// The rest of the current line (without the newline), moving to the next line.
  std::string_view line();
  /// Moves past the next occurrence of `text`; fails when there is none.
  void skipPast(std::string_view text);

  template <class T>
  T binary() {
    static_assert(std::is_arithmetic_v<T>);
    if (data_.size() - pos_ < sizeof(T)) fail("truncated binary data");
    T v;
    std::memcpy(&v, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  /// Skips the single newline (or \r\n) that ends an ASCII header before binary data.
  void skipNewline();

  [[noreturn]] void fail(const std::string& what) const;
  const std::string& file() const { return file_; }

 private:
  void skipSpace() {
    while (pos_ < data_.size() && static_cast<unsigned char>(data_[pos_]) <= ' ') ++pos_;
  }

  std::string_view data_;
  std::string file_;
  std::size_t pos_ = 0;
};

/// Text from a file made fit for a one-line message: at most `max` characters, anything
/// but printable ASCII replaced by '?'.
std::string printable(std::string_view s, std::size_t max = 40);

/// Parses a whole token as an integer / a real number; false when it is not one.
bool parseInteger(std::string_view s, long long& out);
bool parseReal(std::string_view s, double& out);

}  // namespace aniso::io
