#include "io/readers/VtuPayload.h"

#include <zlib.h>

#include <cctype>
#include <cstdint>
#include <cstring>

#include "mesher/core/Error.h"

namespace aniso::io {
namespace {

bool isBase64(unsigned char c) { return std::isalnum(c) || c == '+' || c == '/'; }

int base64Value(unsigned char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  return c == '+' ? 62 : 63;
}

/// Bytes of the encoded array, decoded on demand: fill(n) makes at least n bytes available.
class ByteSource {
 public:
  ByteSource(std::string_view text, bool base64, const std::string& path) : text_(text), base64_(base64), path_(path) {}
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_ + ": " + what); }

  const unsigned char* fill(std::size_t n) {
    if (!base64_) {
      if (n > text_.size()) fail("truncated binary data array");
      return reinterpret_cast<const unsigned char*>(text_.data());
    }
    while (out_.size() < n) {
      if (pos_ >= text_.size()) fail("truncated base64 data array");
      const unsigned char c = static_cast<unsigned char>(text_[pos_++]);
      if (std::isspace(c)) continue;
      if (c == '<') fail("truncated base64 data array");
      if (!isBase64(c) && c != '=') fail("bad base64 data");
      quantum_[q_++] = c == '=' ? 0 : base64Value(c);
      pad_ += c == '=';
      if (q_ < 4) continue;
      const unsigned bits = (quantum_[0] << 18) | (quantum_[1] << 12) | (quantum_[2] << 6) | quantum_[3];
      const unsigned char bytes[3] = {static_cast<unsigned char>(bits >> 16), static_cast<unsigned char>(bits >> 8),
                                      static_cast<unsigned char>(bits)};
      out_.insert(out_.end(), bytes, bytes + 3 - std::min(pad_, 2));
      q_ = pad_ = 0;
    }
    return out_.data();
  }

  std::uint64_t integer(std::size_t at, std::size_t size) {
    std::uint64_t v = 0;
    std::memcpy(&v, fill(at + size) + at, size);  // little-endian
    return v;
  }

 private:
  std::string_view text_;
  bool base64_;
  const std::string& path_;
  std::size_t pos_ = 0;
  std::vector<unsigned char> out_;
  int quantum_[4] = {0, 0, 0, 0}, q_ = 0, pad_ = 0;
};

}  // namespace

std::vector<unsigned char> vtuPayload(std::string_view text, bool base64, const VtuEncoding& enc, std::size_t sizeLimit,
                                      const std::string& path) {
  ByteSource src(text, base64, path);
  const std::size_t hs = enc.headerSize;
  if (!enc.zlib) {
    const std::uint64_t n = src.integer(0, hs);
    if (n > sizeLimit) src.fail("implausible data array size");
    const unsigned char* p = src.fill(hs + n);
    return std::vector<unsigned char>(p + hs, p + hs + n);
  }
  const std::uint64_t blocks = src.integer(0, hs), blockSize = src.integer(hs, hs), lastSize = src.integer(2 * hs, hs);
  if (blocks > sizeLimit || (blocks > 0 && (blockSize == 0 || lastSize > blockSize)) ||
      (blocks > 0 && (blocks - 1) * blockSize + lastSize > sizeLimit))
    src.fail("implausible compressed data array header");
  const std::size_t head = (3 + blocks) * hs;
  std::vector<std::uint64_t> compressed(blocks);
  std::uint64_t total = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    compressed[b] = src.integer((3 + b) * hs, hs);
    total += compressed[b];
    if (total > sizeLimit) src.fail("implausible compressed data array size");
  }
  const unsigned char* p = src.fill(head + total) + head;
  std::vector<unsigned char> out;
  out.reserve(blocks ? (blocks - 1) * blockSize + (lastSize ? lastSize : blockSize) : 0);
  for (std::uint64_t b = 0; b < blocks; ++b) {
    // A last block of size 0 means a full block (VTK's convention).
    const std::uint64_t want = b + 1 == blocks && lastSize != 0 ? lastSize : blockSize;
    const std::size_t at = out.size();
    out.resize(at + want);
    uLongf got = static_cast<uLongf>(want);
    if (uncompress(out.data() + at, &got, p, static_cast<uLong>(compressed[b])) != Z_OK || got != want)
      src.fail("corrupt zlib block " + std::to_string(b) + " in a compressed data array");
    p += compressed[b];
  }
  return out;
}

}  // namespace aniso::io
