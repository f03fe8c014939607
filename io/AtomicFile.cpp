#include "io/AtomicFile.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "mesher/core/Error.h"

namespace aniso::io {

AtomicFile::AtomicFile(std::string target, bool binary)
    : target_(std::move(target)), temp_(target_ + ".tmp" + std::to_string(::getpid())) {
  out_.open(temp_, binary ? std::ios::out | std::ios::binary | std::ios::trunc : std::ios::out | std::ios::trunc);
  if (!out_) throw InputError(target_ + ": cannot write output file here");
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(temp_.c_str());
  }
}

void AtomicFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok) throw MeshingError(target_ + ": write error (disk full?)");
  std::error_code ec;
  // An existing file (or link) is removed first: a rename over it makes ext4 (auto_da_alloc)
  // write the new file's data back before the rename returns (AtomicFile.h).
  const auto st = std::filesystem::symlink_status(target_, ec);
  if (!ec && (std::filesystem::is_regular_file(st) || std::filesystem::is_symlink(st)))
    std::filesystem::remove(target_, ec);  // a failure shows in the rename
  std::filesystem::rename(temp_, target_, ec);
  if (ec) throw MeshingError(target_ + ": cannot rename temporary file: " + ec.message());
  committed_ = true;
}

void writeFileAtomically(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.stream() << text;
  f.commit();
}

}  // namespace aniso::io
