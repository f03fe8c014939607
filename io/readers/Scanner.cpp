// Scanner (Scanner.h) and the whole-file read shared by the mesh readers.
#include "io/readers/Scanner.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "mesher/core/Error.h"

namespace aniso::io {

std::string readWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the file");
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read the file");
  std::string data = s.str();
  if (data.empty()) throw InputError(path + ": empty file");
  return data;
}

std::string printable(std::string_view s, std::size_t max) {
  std::string out;
  for (char c : s.substr(0, max)) out += (c >= ' ' && c <= '~') ? c : '?';
  return out;
}

bool parseInteger(std::string_view s, long long& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size();
}

bool parseReal(std::string_view s, double& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  if (ec == std::errc() && end == s.data() + s.size()) return std::isfinite(out);
  // Fortran-style exponents (1.0D+03), which Abaqus decks may carry.
  std::string t(s);
  std::replace(t.begin(), t.end(), 'D', 'E');
  std::replace(t.begin(), t.end(), 'd', 'e');
  const auto [end2, ec2] = std::from_chars(t.data(), t.data() + t.size(), out);
  return ec2 == std::errc() && end2 == t.data() + t.size() && std::isfinite(out);
}

std::string_view Scanner::token() {
  skipSpace();
  if (pos_ >= data_.size()) fail("unexpected end of file");
  const std::size_t start = pos_;
  while (pos_ < data_.size() && static_cast<unsigned char>(data_[pos_]) > ' ') ++pos_;
  return data_.substr(start, pos_ - start);
}

long long Scanner::integer() {
  const std::string_view t = token();
  long long v = 0;
  if (!parseInteger(t, v)) fail("expected an integer, found '" + printable(t) + "'");
  return v;
}

double Scanner::real() {
  const std::string_view t = token();
  double v = 0;
  if (!parseReal(t, v)) fail("expected a number, found '" + printable(t) + "'");
  return v;
}

void Scanner::expect(std::string_view word) {
  const std::string_view t = token();
  if (t != word) fail("expected " + std::string(word) + ", found '" + printable(t) + "'");
}

std::string_view Scanner::line() {
  const std::size_t start = pos_;
  std::size_t end = data_.find('\n', pos_);
  if (end == std::string_view::npos) end = data_.size();
  pos_ = std::min(end + 1, data_.size());
  std::string_view l = data_.substr(start, end - start);
  if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
  return l;
}

void Scanner::skipPast(std::string_view text) {
  const std::size_t at = data_.find(text, pos_);
  if (at == std::string_view::npos) fail("missing " + std::string(text));
  pos_ = at + text.size();
}

void Scanner::skipNewline() {
  if (pos_ < data_.size() && data_[pos_] == '\r') ++pos_;
  if (pos_ < data_.size() && data_[pos_] == '\n') ++pos_;
}

void Scanner::fail(const std::string& what) const {
  const std::size_t upTo = std::min(pos_, data_.size());
  const long long lineNo = 1 + std::count(data_.begin(), data_.begin() + static_cast<std::ptrdiff_t>(upTo), '\n');
  throw InputError(file_ + ": line " + std::to_string(lineNo) + ": " + what);
}

}  // namespace aniso::io
