#pragma once
// Writing an output file without ever leaving a partial one behind: the content goes to a
// temporary file beside the target, which is renamed over the target only on commit().
// A writer that throws or returns before commit() leaves nothing.
// An existing target (a file or a link) is removed just before the rename: renaming over an
// existing file makes ext4 (auto_da_alloc) write the new file's data back to disk before
// the rename returns (docs/measurements.md), while a new name leaves the writeback to the
// kernel. A reader sees the old file, for an instant no file, then the new one — never a
// partial one.
#include <fstream>
#include <string>

namespace aniso::io {

class AtomicFile {
 public:
  /// Opens "<target>.tmp<pid>" for writing; throws InputError if the folder is not writable.
  explicit AtomicFile(std::string target, bool binary = false);
  ~AtomicFile();  ///< removes the temporary file unless committed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  /// Flushes, closes and renames onto the target; throws MeshingError on an I/O error.
  void commit();

 private:
  std::string target_, temp_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Writes `text` to `path` atomically.
void writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace aniso::io
