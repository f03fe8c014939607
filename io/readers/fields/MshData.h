#pragma once
// MshData — the post-processing sections of a Gmsh MSH file, $NodeData and $ElementData
// (4.1 and 2.2, ASCII and binary; the Gmsh manual's "MSH file format"): string tags (the
// first is the name), real tags, integer tags (time step, components, count), then one
// entry per node / element: its tag (int; binary: int32) and its values (binary: double).
// $ElementNodeData and the interpolation schemes are skipped by the reader.
#include <string>
#include <vector>

#include "io/readers/ReadMesh.h"
#include "io/readers/Scanner.h"
#include "io/readers/TagIndex.h"

namespace aniso::io {

struct MshDataSection {
  bool element = false;  ///< $ElementData
  std::string name;
  int components = 1;
  std::vector<long long> tags;  ///< node or element tags
  std::vector<double> values;   ///< tags.size() × components
};

/// Reads the body of a section whose "$NodeData" / "$ElementData" token was just read, up to
/// and including its end line. Throws InputError (Scanner::fail) on malformed data.
MshDataSection readMshDataSection(Scanner& s, bool binary, bool element);

/// One array per name (the last section of a name wins: the last time step), indexed like
/// `index` (count entries, NaN where the file gives no value). Tags that `index` does not
/// know fail through `s`.
std::vector<MeshData> mshDataArrays(const std::vector<MshDataSection>& sections, bool element, const TagIndex& index,
                                    std::size_t count, Scanner& s);

}  // namespace aniso::io
