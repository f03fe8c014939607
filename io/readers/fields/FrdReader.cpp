// CalculiX result file reader (.frd, ASCII; the CalculiX / CGX manual's "Result Format"):
//   "    2C" node block: " -1" node number, x y z;        " -3" ends it
//   "    3C" element block: " -1" element number, type, group, material; " -2" node lines
//   "  100C" result block: " -4" name and component count, " -5" one line per component
//            (those flagged "exists" in their 5th integer, DISP's "ALL", are not stored),
//            then per node " -1" number and values (continued on " -2" lines), " -3" ends it
// Numbers are in fixed columns (values run together: "1.0E+00-2.0E+00"): an integer field
// is 5 characters (format 0) or 10 (format 1, the last integer of the 2C / 3C / 100C
// line); values are 12 characters. Of results with the same name the last block is kept
// (the last step). Binary FRD (format 2) is refused. Element types: FRD 1..12 (he8 pe6
// te4 he20 pe15 te10 tr3 tr6 qu4 qu8 be2 be3); the te10 / tr6 node order is ours.
#include <cmath>
#include <limits>
#include <map>

#include "io/readers/ReadMesh.h"
#include "io/readers/Scanner.h"
#include "io/readers/TagIndex.h"
#include "mesher/core/Error.h"

namespace aniso::io {
namespace {

constexpr int kValueWidth = 12;

struct FrdType {
  CellType type;
  int nodes;
};

bool frdType(long long id, FrdType& out) {
  static const FrdType table[] = {{CellType::Hex, 8},       {CellType::Prism, 6},    {CellType::Tet, 4},
                                  {CellType::Hex20, 20},    {CellType::Prism15, 15}, {CellType::Tet10, 10},
                                  {CellType::Triangle, 3},  {CellType::Triangle6, 6}, {CellType::Quad, 4},
                                  {CellType::Quad8, 8},     {CellType::Line, 2},     {CellType::Line3, 3}};
  if (id < 1 || id > 12) return false;
  out = table[id - 1];
  return true;
}

class FrdParser {
 public:
  FrdParser(const std::string& data, const std::string& path) : data_(data), path_(path) {}
  ReadMesh parse();

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_ + ": line " + std::to_string(lineNo_) + ": " + what);
  }
  /// Fixed columns: lines are taken whole, leading blanks included.
  bool atEnd() const { return pos_ >= data_.size(); }
  std::string_view nextLine() {
    const std::size_t end = std::min(data_.find('\n', pos_), data_.size());
    std::string_view l(data_.data() + pos_, end - pos_);
    pos_ = std::min(end + 1, data_.size());
    ++lineNo_;
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    return l;
  }
  /// The record key of a line: "-1", "-2", "-3", "-4", "-5" or the block key ("2C", "100C"...).
  static std::string_view key(std::string_view line);
  int formatOf(std::string_view header);
  long long intField(std::string_view line, std::size_t& at, int width);
  double realField(std::string_view line, std::size_t& at);
  void nodes(std::string_view header);
  void elements(std::string_view header);
  void results(std::string_view header);

  std::string_view data_;
  std::string path_;
  std::size_t pos_ = 0;
  long long lineNo_ = 0;
  std::vector<long long> nodeIds_, connIds_;
  ReadMesh m_;
  std::map<std::string, MeshData> results_;
  std::vector<std::string> order_;
};

std::string_view FrdParser::key(std::string_view line) {
  std::size_t i = 0;
  while (i < line.size() && line[i] == ' ') ++i;
  std::size_t j = i;
  if (j < line.size() && line[j] == '-') ++j;
  while (j < line.size() && line[j] >= '0' && line[j] <= '9') ++j;
  if (j < line.size() && line[i] != '-' && (line[j] == 'C' || line[j] == 'P' || line[j] == 'U')) ++j;
  return line.substr(i, j - i);
}

int FrdParser::formatOf(std::string_view header) {
  std::size_t end = header.size();
  while (end > 0 && header[end - 1] == ' ') --end;
  std::size_t start = end;
  while (start > 0 && header[start - 1] != ' ') --start;
  long long f = 0;
  if (!parseInteger(header.substr(start, end - start), f) || f < 0 || f > 2) fail("unreadable block format");
  if (f == 2) fail("binary FRD is not supported (write ASCII results: no OUTPUT=BINARY)");
  return static_cast<int>(f);
}

long long FrdParser::intField(std::string_view line, std::size_t& at, int width) {
  if (at + width > line.size()) fail("a record is too short");
  std::string_view f = line.substr(at, width);
  at += width;
  while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
  long long v = 0;
  if (!parseInteger(f, v)) fail("'" + printable(f) + "' is not an integer");
  return v;
}

double FrdParser::realField(std::string_view line, std::size_t& at) {
  const std::size_t width = std::min<std::size_t>(kValueWidth, line.size() - at);
  std::string_view f = line.substr(at, width);
  at += width;
  while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
  double v = 0;
  if (!parseReal(f, v)) fail("'" + printable(f) + "' is not a number");
  return v;
}

void FrdParser::nodes(std::string_view header) {
  const int w = formatOf(header) == 1 ? 10 : 5;
  for (;;) {
    if (atEnd()) fail("unterminated node block");
    const std::string_view line = nextLine();
    const std::string_view k = key(line);
    if (k == "-3") return;
    if (k != "-1") fail("unexpected record in the node block");
    std::size_t at = 3;
    nodeIds_.push_back(intField(line, at, w));
    Vec3 p;
    for (int c = 0; c < 3; ++c) p[c] = realField(line, at);
    m_.nodes.push_back(p);
  }
}

void FrdParser::elements(std::string_view header) {
  const int w = formatOf(header) == 1 ? 10 : 5;
  for (;;) {
    if (atEnd()) fail("unterminated element block");
    std::string_view line = nextLine();
    std::string_view k = key(line);
    if (k == "-3") return;
    if (k != "-1") fail("unexpected record in the element block");
    std::size_t at = 3;
    intField(line, at, w);
    FrdType t;
    if (!frdType(intField(line, at, 5), t)) fail("unsupported FRD element type");
    std::vector<long long> ids;
    while (static_cast<int>(ids.size()) < t.nodes) {
      if (atEnd()) fail("truncated element");
      line = nextLine();
      if (key(line) != "-2") fail("an element has too few nodes");
      for (at = 3; at + w <= line.size() && static_cast<int>(ids.size()) < t.nodes;) ids.push_back(intField(line, at, w));
    }
    m_.types.push_back(t.type);
    connIds_.insert(connIds_.end(), ids.begin(), ids.end());
  }
}

void FrdParser::results(std::string_view header) {
  const int w = formatOf(header) == 1 ? 10 : 5;
  MeshData d;
  std::vector<std::string> names;
  std::string_view line;
  for (;;) {  // the -4 line and the -5 component lines
    if (atEnd()) fail("truncated result block");
    line = nextLine();
    const std::string_view k = key(line);
    if (k == "-4") {
      std::size_t i = 3;
      while (i < line.size() && line[i] == ' ') ++i;
      std::size_t j = i;
      while (j < line.size() && line[j] != ' ') ++j;
      d.name = std::string(line.substr(i, j - i));
    } else if (k == "-5") {
      std::size_t i = 3;
      while (i < line.size() && line[i] == ' ') ++i;
      std::size_t j = i;
      while (j < line.size() && line[j] != ' ') ++j;
      const std::string name(line.substr(i, j - i));
      // the 5th integer after the name (A8 from column 5) flags a component computed by the
      // reader (DISP's ALL)
      std::size_t at = 13, n = 0;
      long long v = 0, exists = 0;
      while (n < 5 && at + 5 <= line.size()) {
        std::string_view f = line.substr(at, 5);
        while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
        while (!f.empty() && !(f.back() >= '0' && f.back() <= '9')) f.remove_suffix(1);
        if (!parseInteger(f, v)) break;
        if (++n == 5) exists = v;
        at += 5;
      }
      if (exists != 1) names.push_back(name);
    } else {
      break;
    }
  }
  if (d.name.empty()) fail("a result block without its -4 name record");
  d.components = static_cast<int>(names.size());
  if (d.components < 1) fail("result " + d.name + " has no components");
  d.componentNames = names;
  TagIndex index;
  index.build(nodeIds_);
  d.values.assign(m_.nodes.size() * d.components, std::numeric_limits<double>::quiet_NaN());
  for (;;) {
    const std::string_view k = key(line);
    if (k == "-3") break;
    if (k != "-1") fail("unexpected record in result " + d.name);
    std::size_t at = 3;
    const int node = index.find(intField(line, at, w));
    if (node < 0) fail("result " + d.name + " for a node that is not defined");
    for (int c = 0; c < d.components; ++c) {
      if (at >= line.size()) {  // continued on a -2 line
        if (atEnd()) fail("truncated result " + d.name);
        line = nextLine();
        if (key(line) != "-2") fail("result " + d.name + ": too few values for a node");
        at = 3 + w;
      }
      d.values[node * d.components + c] = realField(line, at);
    }
    if (atEnd()) fail("unterminated result " + d.name);
    line = nextLine();
  }
  if (!results_.count(d.name)) order_.push_back(d.name);
  results_[d.name] = std::move(d);
}

ReadMesh FrdParser::parse() {
  m_.format = "frd";
  bool sawNodes = false;
  while (!atEnd()) {
    const std::string_view line = nextLine();
    const std::string_view k = key(line);
    if (k == "2C") {
      nodes(line);
      sawNodes = true;
    } else if (k == "3C") {
      elements(line);
    } else if (k == "100C") {
      if (!sawNodes) fail("results before the nodes");
      results(line);
    } else if (k == "9999") {
      break;
    }
  }
  if (!sawNodes) fail("not a CalculiX result file (no node block)");
  TagIndex index;
  if (!index.build(nodeIds_)) fail("a node number is used twice");
  for (long long id : connIds_) {
    const int i = index.find(id);
    if (i < 0) fail("an element refers to node " + std::to_string(id) + ", which is not defined");
    m_.conn.push_back(i);
  }
  for (CellType t : m_.types) m_.offsets.push_back(m_.offsets.back() + cellNodeCount(t));
  for (const std::string& name : order_) m_.pointData.push_back(std::move(results_[name]));
  return std::move(m_);
}

}  // namespace

ReadMesh readFrd(const std::string& path) {
  const std::string data = readWholeFile(path);
  return FrdParser(data, path).parse();
}

}  // namespace aniso::io
