// VTK XML unstructured grid reader (.vtu): the Piece's Points, Cells (connectivity,
// offsets, types), integer CellData arrays (as groups) and every PointData / CellData array
// (ReadMesh::pointData, cellData). Data arrays ASCII, inline
// base64 ("binary") or appended (raw or base64), headers UInt32 or UInt64, little-endian,
// uncompressed or zlib-compressed (VtuPayload.h). The XML is scanned, not fully parsed: enough for the files VTK, meshio,
// ParaView and our writer produce.
#include <cctype>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <string_view>

#include "io/readers/ReadMesh.h"
#include "io/readers/Scanner.h"
#include "io/readers/VtuPayload.h"
#include "mesher/core/Error.h"

namespace aniso::io {
namespace {

/// An integer cell-data array with more distinct values than this is not a grouping (an
/// id per element, say) and gives no groups.
constexpr std::size_t kMaxGroupsPerArray = 1000;

struct Tag {
  std::string name;
  std::map<std::string, std::string> attr;
  std::size_t end = 0;  ///< position after '>'
  bool closes = false, selfClosing = false;
};

struct DataArray {
  std::map<std::string, std::string> attr;
  std::string section;          ///< enclosing Points / Cells / CellData / PointData / FieldData
  std::string_view content;     ///< text between the tags (ascii, binary)
};

class VtuParser {
 public:
  VtuParser(const std::string& data, const std::string& path) : data_(data), path_(path) {}
  ReadMesh parse();

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(path_ + ": " + what); }
  bool nextTag(std::size_t& pos, Tag& tag) const;
  std::vector<double> values(const DataArray& a) const;
  std::vector<unsigned char> binaryBytes(const DataArray& a) const;
  std::vector<double> decode(const std::string& type, const unsigned char* p, std::size_t bytes) const;
  const DataArray& cellArray(const char* name) const;
  void dataArrays(ReadMesh& m) const;

  const std::string& data_;
  std::string path_;
  VtuEncoding encoding_;
  std::size_t appended_ = std::string::npos;  ///< first byte after '_'
  bool appendedBase64_ = false;
  std::vector<DataArray> arrays_;
};

bool VtuParser::nextTag(std::size_t& pos, Tag& tag) const {
  for (;;) {
    const std::size_t lt = data_.find('<', pos);
    if (lt == std::string::npos) return false;
    if (data_.compare(lt, 4, "<!--") == 0) {
      const std::size_t e = data_.find("-->", lt);
      if (e == std::string::npos) fail("unterminated XML comment");
      pos = e + 3;
      continue;
    }
    if (data_.compare(lt, 2, "<?") == 0) {
      pos = data_.find("?>", lt);
      if (pos == std::string::npos) fail("malformed XML");
      pos += 2;
      continue;
    }
    const std::size_t gt = data_.find('>', lt);
    if (gt == std::string::npos) fail("malformed XML (a tag is not closed)");
    std::string_view body(data_.data() + lt + 1, gt - lt - 1);
    tag = Tag{};
    tag.end = gt + 1;
    tag.closes = !body.empty() && body.front() == '/';
    if (tag.closes) body.remove_prefix(1);
    tag.selfClosing = !body.empty() && body.back() == '/';
    if (tag.selfClosing) body.remove_suffix(1);
    std::size_t i = 0;
    while (i < body.size() && !std::isspace(static_cast<unsigned char>(body[i]))) ++i;
    tag.name = std::string(body.substr(0, i));
    while (i < body.size()) {  // name="value" pairs
      while (i < body.size() && std::isspace(static_cast<unsigned char>(body[i]))) ++i;
      const std::size_t eq = body.find('=', i);
      if (eq == std::string_view::npos) break;
      std::string key(body.substr(i, eq - i));
      while (!key.empty() && std::isspace(static_cast<unsigned char>(key.back()))) key.pop_back();
      std::size_t q = eq + 1;
      while (q < body.size() && std::isspace(static_cast<unsigned char>(body[q]))) ++q;
      if (q >= body.size() || (body[q] != '"' && body[q] != '\'')) fail("malformed XML attribute in <" + tag.name + ">");
      const std::size_t close = body.find(body[q], q + 1);
      if (close == std::string_view::npos) fail("malformed XML attribute in <" + tag.name + ">");
      tag.attr[key] = std::string(body.substr(q + 1, close - q - 1));
      i = close + 1;
    }
    pos = tag.end;
    return true;
  }
}

std::vector<double> VtuParser::decode(const std::string& type, const unsigned char* p, std::size_t bytes) const {
  auto read = [&](auto zero) {
    using T = decltype(zero);
    if (bytes % sizeof(T)) fail("a " + type + " data array has " + std::to_string(bytes) + " bytes");
    std::vector<double> out(bytes / sizeof(T));
    for (std::size_t i = 0; i < out.size(); ++i) {
      T v;
      std::memcpy(&v, p + i * sizeof(T), sizeof(T));
      out[i] = static_cast<double>(v);
    }
    return out;
  };
  if (type == "Float64") return read(double{});
  if (type == "Float32") return read(float{});
  if (type == "Int64") return read(std::int64_t{});
  if (type == "UInt64") return read(std::uint64_t{});
  if (type == "Int32") return read(std::int32_t{});
  if (type == "UInt32") return read(std::uint32_t{});
  if (type == "Int16") return read(std::int16_t{});
  if (type == "UInt16") return read(std::uint16_t{});
  if (type == "Int8") return read(std::int8_t{});
  if (type == "UInt8") return read(std::uint8_t{});
  fail("unsupported data array type " + type);
}

std::vector<unsigned char> VtuParser::binaryBytes(const DataArray& a) const {
  const auto fmt = a.attr.find("format");
  // zlib inflates at most ~1032:1; anything claiming more than that is corrupt.
  const std::size_t limit = (encoding_.zlib ? 1100 : 4) * data_.size() + 1024;
  if (fmt == a.attr.end() || fmt->second != "appended") return vtuPayload(a.content, true, encoding_, limit, path_);
  if (appended_ == std::string::npos) fail("an appended data array but no <AppendedData>");
  const auto off = a.attr.find("offset");
  long long offset = 0;
  if (off == a.attr.end() || !parseInteger(off->second, offset) || offset < 0 ||
      appended_ + static_cast<std::size_t>(offset) > data_.size())
    fail("appended data array without a valid offset");
  const std::string_view rest(data_.data() + appended_ + offset, data_.size() - appended_ - offset);
  return vtuPayload(rest, appendedBase64_, encoding_, limit, path_);
}

std::vector<double> VtuParser::values(const DataArray& a) const {
  const auto type = a.attr.find("type");
  if (type == a.attr.end()) fail("a data array has no type");
  const auto fmt = a.attr.find("format");
  const std::string format = fmt == a.attr.end() ? "ascii" : fmt->second;
  if (format == "ascii") {
    std::vector<double> out;
    Scanner s(a.content, path_);
    while (!s.atEnd()) out.push_back(s.real());
    return out;
  }
  if (format != "binary" && format != "appended") fail("unsupported data array format " + format);
  const std::vector<unsigned char> bytes = binaryBytes(a);
  return decode(type->second, bytes.data(), bytes.size());
}

const DataArray& VtuParser::cellArray(const char* name) const {
  for (const DataArray& a : arrays_) {
    const auto n = a.attr.find("Name");
    if (a.section == "Cells" && n != a.attr.end() && n->second == name) return a;
  }
  fail(std::string("no <Cells> data array named ") + name);
}

/// Every PointData and CellData array, as ReadMesh::MeshData.
void VtuParser::dataArrays(ReadMesh& m) const {
  for (const DataArray& a : arrays_) {
    if (a.section != "PointData" && a.section != "CellData") continue;
    MeshData d;
    d.name = a.attr.count("Name") ? a.attr.at("Name") : "data";
    long long comps = 1;
    if (a.attr.count("NumberOfComponents") && (!parseInteger(a.attr.at("NumberOfComponents"), comps) || comps < 1 || comps > 81))
      fail("data array " + d.name + " has a bad NumberOfComponents");
    d.components = static_cast<int>(comps);
    d.values = values(a);
    const bool point = a.section == "PointData";
    const std::size_t count = point ? m.nodes.size() : m.cellCount();
    if (d.values.size() != count * d.components)
      fail((point ? "point" : "cell") + std::string(" data ") + d.name + " has " + std::to_string(d.values.size()) +
           " values for " + std::to_string(count) + (point ? " points" : " cells"));
    (point ? m.pointData : m.cellData).push_back(std::move(d));
  }
}

bool vtkType(int id, CellType& out) {
  static const std::map<int, CellType> table = {
      {1, CellType::Point},      {3, CellType::Line},       {5, CellType::Triangle},  {7, CellType::Polygon},
      {9, CellType::Quad},       {10, CellType::Tet},       {12, CellType::Hex},      {13, CellType::Prism},
      {14, CellType::Pyramid},   {21, CellType::Line3},     {22, CellType::Triangle6}, {23, CellType::Quad8},
      {24, CellType::Tet10},     {25, CellType::Hex20},     {26, CellType::Prism15},  {27, CellType::Pyramid13},
      {28, CellType::Quad9},     {29, CellType::Hex27},     {32, CellType::Prism18}};
  const auto it = table.find(id);
  if (it == table.end()) return false;
  out = it->second;
  return true;
}

ReadMesh VtuParser::parse() {
  std::size_t pos = 0;
  Tag tag;
  std::vector<std::string> open;
  bool sawFile = false, sawPiece = false;
  while (nextTag(pos, tag)) {
    if (tag.closes) {
      if (!open.empty()) open.pop_back();
      continue;
    }
    if (tag.name == "VTKFile") {
      sawFile = true;
      if (tag.attr["type"] != "UnstructuredGrid") fail("not a VTK unstructured grid (type=\"" + tag.attr["type"] + "\")");
      if (tag.attr.count("byte_order") && tag.attr["byte_order"] != "LittleEndian") fail("big-endian VTU is not supported");
      const std::string compressor = tag.attr.count("compressor") ? tag.attr["compressor"] : "";
      if (!compressor.empty() && compressor != "vtkZLibDataCompressor")
        fail("compressed VTU (" + compressor + ") is not supported; zlib is");
      encoding_.zlib = !compressor.empty();
      encoding_.headerSize = tag.attr.count("header_type") && tag.attr["header_type"] == "UInt64" ? 8 : 4;
    } else if (tag.name == "Piece") {
      if (sawPiece) fail("more than one <Piece> is not supported");
      sawPiece = true;
    } else if (tag.name == "DataArray") {
      DataArray a{tag.attr, open.empty() ? "" : open.back(), {}};
      if (!tag.selfClosing) {
        const std::size_t close = data_.find("</DataArray>", pos);
        if (close == std::string::npos) fail("unterminated <DataArray>");
        a.content = std::string_view(data_.data() + pos, close - pos);
        pos = close + std::strlen("</DataArray>");
      }
      arrays_.push_back(std::move(a));
      continue;
    } else if (tag.name == "AppendedData") {
      appendedBase64_ = tag.attr["encoding"] == "base64";
      const std::size_t underscore = data_.find('_', pos);
      if (underscore == std::string::npos) fail("<AppendedData> without its '_' marker");
      appended_ = underscore + 1;
      break;  // raw bytes follow: no more tags to read
    }
    if (!tag.selfClosing) open.push_back(tag.name);
  }
  if (!sawFile) fail("not a VTK XML file (no <VTKFile>)");
  if (!sawPiece) fail("no <Piece> in the file");

  ReadMesh m;
  m.format = "vtu";
  const DataArray* points = nullptr;
  for (const DataArray& a : arrays_)
    if (a.section == "Points") points = &a;
  if (!points) fail("no <Points> data array");
  const std::vector<double> xyz = values(*points);
  if (xyz.size() % 3) fail("the point coordinates are not triples");
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) m.nodes.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);

  const std::vector<double> conn = values(cellArray("connectivity")), offsets = values(cellArray("offsets")),
                            types = values(cellArray("types"));
  if (offsets.size() != types.size()) fail("offsets and types differ in length");
  std::size_t start = 0;
  for (std::size_t i = 0; i < types.size(); ++i) {
    CellType t;
    if (!vtkType(static_cast<int>(types[i]), t)) fail("unsupported VTK cell type " + std::to_string(static_cast<int>(types[i])));
    const auto end = static_cast<std::size_t>(offsets[i]);
    if (offsets[i] < 0 || end < start || end > conn.size()) fail("bad cell offsets");
    const int n = static_cast<int>(end - start);
    if (t == CellType::Polygon && n == 3) t = CellType::Triangle;
    if (t == CellType::Polygon && n == 4) t = CellType::Quad;
    if ((t == CellType::Polygon && n < 3) || (t != CellType::Polygon && n != cellNodeCount(t)))
      fail("a " + std::string(cellTypeName(t)) + " cell has " + std::to_string(n) + " nodes");
    std::vector<int> nodes(conn.begin() + start, conn.begin() + end);
    m.addCell(t, nodes.data(), n);
    start = end;
  }
  // Groups: each integer cell-data array of one component, by value.
  for (const DataArray& a : arrays_) {
    if (a.section != "CellData") continue;
    const auto type = a.attr.find("type");
    const auto comps = a.attr.find("NumberOfComponents");
    if (type == a.attr.end() || type->second.find("Int") == std::string::npos) continue;
    if (comps != a.attr.end() && comps->second != "1") continue;
    const std::vector<double> v = values(a);
    if (v.size() != m.cellCount()) fail("cell data " + a.attr.at("Name") + " has " + std::to_string(v.size()) + " values");
    std::map<long long, std::vector<int>> byValue;
    for (std::size_t i = 0; i < v.size() && byValue.size() <= kMaxGroupsPerArray; ++i)
      byValue[static_cast<long long>(v[i])].push_back(static_cast<int>(i));
    if (byValue.size() > kMaxGroupsPerArray) continue;
    const std::string name = a.attr.count("Name") ? a.attr.at("Name") : "cell_data";
    for (auto& [value, cells] : byValue) m.groups.push_back({name + "=" + std::to_string(value), std::move(cells)});
  }
  dataArrays(m);
  return m;
}

}  // namespace

ReadMesh readVtu(const std::string& path) {
  const std::string data = readWholeFile(path);
  return VtuParser(data, path).parse();
}

}  // namespace aniso::io
