#pragma once
// VtuPayload — the data bytes of one binary DataArray of a VTK XML file, as VTK, ParaView
// and meshio write them:
//   - inline "binary": base64 text; appended: raw bytes or base64 text after '_';
//   - uncompressed: a header (the byte count, UInt32 or UInt64) then the bytes;
//   - zlib-compressed (compressor="vtkZLibDataCompressor"): a header of 3 + n integers
//     (block count n, uncompressed block size, size of the last block, then the n
//     compressed sizes) then the n zlib streams, inflated and concatenated here.
// Base64 header and data may be encoded together or one after the other, each padded: the
// text is decoded quantum by quantum, so both read the same.
// Throws InputError("PATH: what") on truncated, malformed or implausible data; never reads
// past `text`.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace aniso::io {

struct VtuEncoding {
  std::size_t headerSize = 4;  ///< bytes per header integer: 4 (UInt32) or 8 (UInt64)
  bool zlib = false;           ///< compressor="vtkZLibDataCompressor"
};

/// The uncompressed data bytes of the array whose encoded form starts at text[0] (base64
/// when `base64`, raw otherwise). `sizeLimit` bounds the plausible uncompressed size.
std::vector<unsigned char> vtuPayload(std::string_view text, bool base64, const VtuEncoding& enc,
                                      std::size_t sizeLimit, const std::string& path);

}  // namespace aniso::io
