// Gmsh MSH reader: 4.1 and 2.2, ASCII and binary (little-endian, 8-byte data size), the
// sections $MeshFormat $PhysicalNames $Entities $Nodes $Elements $NodeData $ElementData
// (fields/MshData.h); other sections skipped.
#include <algorithm>
#include <array>
#include <map>
#include <utility>

#include "io/readers/ReadMesh.h"
#include "io/readers/Scanner.h"
#include "io/readers/TagIndex.h"
#include "io/readers/fields/MshData.h"

namespace aniso::io {
namespace {

struct GmshType {
  CellType type;
  int nodes;
};

/// Gmsh element type ids 1..19 (the manual's "MSH file format" list).
bool gmshType(long long id, GmshType& out) {
  static const GmshType table[] = {
      {CellType::Line, 2},     {CellType::Triangle, 3}, {CellType::Quad, 4},      {CellType::Tet, 4},
      {CellType::Hex, 8},      {CellType::Prism, 6},    {CellType::Pyramid, 5},   {CellType::Line3, 3},
      {CellType::Triangle6, 6}, {CellType::Quad9, 9},   {CellType::Tet10, 10},    {CellType::Hex27, 27},
      {CellType::Prism18, 18}, {CellType::Pyramid14, 14}, {CellType::Point, 1},   {CellType::Quad8, 8},
      {CellType::Hex20, 20},   {CellType::Prism15, 15}, {CellType::Pyramid13, 13}};
  if (id < 1 || id > 19) return false;
  out = table[id - 1];
  return true;
}

using Key = std::pair<int, long long>;  ///< (dimension, tag)

class MshParser {
 public:
  MshParser(const std::string& data, const std::string& path) : s_(data, path), size_(data.size()) {}

  ReadMesh parse();

 private:
  void header();
  void physicalNames();
  void entities();
  void nodes41();
  void nodes22();
  void elements41();
  void elements22();
  /// A count read from the file: no larger than the file could hold.
  std::size_t count(long long n) {
    if (n < 0 || static_cast<std::size_t>(n) > size_) s_.fail("implausible count " + std::to_string(n));
    return static_cast<std::size_t>(n);
  }
  long long sizeT() { return binary_ ? static_cast<long long>(s_.binary<std::uint64_t>()) : s_.integer(); }
  long long int32() { return binary_ ? s_.binary<std::int32_t>() : s_.integer(); }
  double real() { return binary_ ? s_.binary<double>() : s_.real(); }
  void addElement(long long type, int dim, const std::vector<long long>& groupTags, long long* nodeTags);
  ReadMesh finish();

  Scanner s_;
  std::size_t size_;
  bool binary_ = false;
  bool v41_ = true;
  std::map<Key, std::string> names_;
  std::map<Key, std::vector<long long>> entityPhysicals_;
  std::vector<long long> nodeTags_;
  std::vector<Vec3> nodes_;
  std::vector<CellType> types_;
  std::vector<long long> connTags_;
  std::vector<long long> cellTags_;
  std::vector<MshDataSection> data_;
  std::map<Key, std::vector<int>> groups_;
};

void MshParser::header() {
  if (s_.atEnd() || s_.token() != "$MeshFormat") s_.fail("not a Gmsh MSH file (no $MeshFormat)");
  const std::string_view version = s_.token();
  if (version == "2.2" || version == "2.1" || version == "2") {
    v41_ = false;
  } else if (version != "4.1") {
    s_.fail("MSH version " + std::string(version) + " is not supported (4.1 and 2.2 are)");
  }
  const long long fileType = s_.integer(), dataSize = s_.integer();
  binary_ = fileType == 1;
  if (binary_) {
    if (dataSize != 8) s_.fail("binary MSH with data size " + std::to_string(dataSize) + " is not supported");
    s_.skipNewline();
    if (s_.binary<std::int32_t>() != 1) s_.fail("big-endian binary MSH is not supported");
  }
  s_.expect("$EndMeshFormat");
}

void MshParser::physicalNames() {
  const std::size_t n = count(s_.integer());
  for (std::size_t i = 0; i < n; ++i) {
    const int dim = static_cast<int>(s_.integer());
    const long long tag = s_.integer();
    std::string_view name = s_.line();
    while (!name.empty() && (name.front() == ' ' || name.front() == '\t')) name.remove_prefix(1);
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"') name = name.substr(1, name.size() - 2);
    names_[{dim, tag}] = std::string(name);
  }
  s_.expect("$EndPhysicalNames");
}

void MshParser::entities() {
  std::array<std::size_t, 4> n;
  for (auto& c : n) c = count(sizeT());
  for (int dim = 0; dim < 4; ++dim)
    for (std::size_t i = 0; i < n[dim]; ++i) {
      const long long tag = int32();
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) real();
      std::vector<long long>& phys = entityPhysicals_[{dim, tag}];
      const std::size_t np = count(sizeT());
      for (std::size_t k = 0; k < np; ++k) phys.push_back(int32());
      if (dim == 0) continue;
      const std::size_t nb = count(sizeT());
      for (std::size_t k = 0; k < nb; ++k) int32();
    }
  s_.expect("$EndEntities");
}

void MshParser::nodes41() {
  const std::size_t blocks = count(sizeT());
  const std::size_t total = count(sizeT());
  sizeT();
  sizeT();
  nodeTags_.reserve(total);
  nodes_.reserve(total);
  for (std::size_t b = 0; b < blocks; ++b) {
    const long long dim = int32();
    int32();
    const long long parametric = int32();
    const std::size_t n = count(sizeT());
    for (std::size_t i = 0; i < n; ++i) nodeTags_.push_back(sizeT());
    const int extra = parametric ? static_cast<int>(dim) : 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = real(), y = real(), z = real();
      nodes_.emplace_back(x, y, z);
      for (int k = 0; k < extra; ++k) real();
    }
  }
  if (nodes_.size() != total) s_.fail("$Nodes announces " + std::to_string(total) + " nodes but has " + std::to_string(nodes_.size()));
  s_.expect("$EndNodes");
}

void MshParser::nodes22() {
  const std::size_t n = count(s_.integer());
  if (binary_) s_.skipNewline();
  for (std::size_t i = 0; i < n; ++i) {
    nodeTags_.push_back(int32());
    const double x = real(), y = real(), z = real();
    nodes_.emplace_back(x, y, z);
  }
  s_.expect("$EndNodes");
}

void MshParser::addElement(long long type, int dim, const std::vector<long long>& groupTags, long long* nodeTags) {
  GmshType t;
  gmshType(type, t);
  if (t.type == CellType::Tet10) std::swap(nodeTags[8], nodeTags[9]);  // Gmsh: (3,2) (3,1)
  const int cell = static_cast<int>(types_.size());
  types_.push_back(t.type);
  connTags_.insert(connTags_.end(), nodeTags, nodeTags + t.nodes);
  for (long long g : groupTags) groups_[{dim, g}].push_back(cell);
}

void MshParser::elements41() {
  const std::size_t blocks = count(sizeT());
  const std::size_t total = count(sizeT());
  sizeT();
  sizeT();
  std::vector<long long> tags(32);
  const std::vector<long long> none;
  for (std::size_t b = 0; b < blocks; ++b) {
    const int dim = static_cast<int>(int32());
    const long long entity = int32();
    const long long type = int32();
    const std::size_t n = count(sizeT());
    GmshType t;
    if (!gmshType(type, t)) s_.fail("unsupported element type " + std::to_string(type));
    const auto phys = entityPhysicals_.find({dim, entity});
    const std::vector<long long>& groups = phys == entityPhysicals_.end() ? none : phys->second;
    for (std::size_t i = 0; i < n; ++i) {
      cellTags_.push_back(sizeT());
      for (int k = 0; k < t.nodes; ++k) tags[k] = sizeT();
      addElement(type, dim, groups, tags.data());
    }
  }
  if (types_.size() != total) s_.fail("$Elements announces " + std::to_string(total) + " elements but has " + std::to_string(types_.size()));
  s_.expect("$EndElements");
}

void MshParser::elements22() {
  const std::size_t total = count(s_.integer());
  if (binary_) s_.skipNewline();
  std::vector<long long> tags(32), groups;
  auto one = [&](long long type, long long ntags) {
    GmshType t;
    if (!gmshType(type, t)) s_.fail("unsupported element type " + std::to_string(type));
    groups.clear();
    for (long long k = 0; k < ntags; ++k) {
      const long long tag = int32();
      if (k == 0 && tag != 0) groups.push_back(tag);  // the first tag is the physical group
    }
    for (int k = 0; k < t.nodes; ++k) tags[k] = int32();
    addElement(type, cellDimension(t.type), groups, tags.data());
  };
  if (!binary_) {
    for (std::size_t i = 0; i < total; ++i) {
      cellTags_.push_back(s_.integer());
      const long long type = s_.integer(), ntags = static_cast<long long>(count(s_.integer()));
      one(type, ntags);
    }
  } else {
    while (types_.size() < total) {
      const long long type = int32();
      const std::size_t n = count(int32());
      const long long ntags = static_cast<long long>(count(int32()));
      if (n == 0) s_.fail("empty element block");
      for (std::size_t i = 0; i < n; ++i) {
        cellTags_.push_back(int32());
        one(type, ntags);
      }
    }
  }
  s_.expect("$EndElements");
}

ReadMesh MshParser::finish() {
  ReadMesh m;
  m.format = std::string("msh") + (v41_ ? "4.1" : "2.2") + (binary_ ? " binary" : " ascii");
  TagIndex index;
  if (!index.build(nodeTags_)) s_.fail("a node tag is used twice");
  m.nodes = std::move(nodes_);
  m.types = std::move(types_);
  m.conn.reserve(connTags_.size());
  m.offsets.reserve(m.types.size() + 1);
  std::size_t at = 0;
  for (CellType t : m.types) {
    for (int k = 0; k < cellNodeCount(t); ++k) {
      const int i = index.find(connTags_[at++]);
      if (i < 0) s_.fail("an element refers to node " + std::to_string(connTags_[at - 1]) + ", which is not defined");
      m.conn.push_back(i);
    }
    m.offsets.push_back(static_cast<int>(m.conn.size()));
  }
  if (!data_.empty()) {
    m.pointData = mshDataArrays(data_, false, index, m.nodes.size(), s_);
    TagIndex cells;
    if (!cells.build(cellTags_) && std::any_of(data_.begin(), data_.end(), [](const auto& d) { return d.element; }))
      s_.fail("an element tag is used twice");
    m.cellData = mshDataArrays(data_, true, cells, m.types.size(), s_);
  }
  for (auto& [key, cells] : groups_) {
    const auto name = names_.find(key);
    m.groups.push_back({name != names_.end() ? name->second : std::to_string(key.first) + ":" + std::to_string(key.second),
                        std::move(cells)});
  }
  return m;
}

ReadMesh MshParser::parse() {
  header();
  while (!s_.atEnd()) {
    const std::string section(s_.token());
    if (binary_ && v41_ && (section == "$Entities" || section == "$Nodes" || section == "$Elements")) s_.skipNewline();
    if (section == "$PhysicalNames") {
      physicalNames();
    } else if (section == "$Entities" && v41_) {
      entities();
    } else if (section == "$Nodes") {
      v41_ ? nodes41() : nodes22();
    } else if (section == "$Elements") {
      v41_ ? elements41() : elements22();
    } else if (section == "$NodeData" || section == "$ElementData") {
      data_.push_back(readMshDataSection(s_, binary_, section == "$ElementData"));
    } else if (section.size() > 1 && section[0] == '$') {
      s_.skipPast("$End" + section.substr(1));
    } else {
      s_.fail("unexpected '" + section.substr(0, 40) + "' between sections");
    }
  }
  return finish();
}

}  // namespace

ReadMesh readMsh(const std::string& path) {
  const std::string data = readWholeFile(path);
  return MshParser(data, path).parse();
}

}  // namespace aniso::io
