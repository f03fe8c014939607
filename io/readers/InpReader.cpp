// Abaqus / CalculiX input deck reader: *NODE, *ELEMENT, *ELSET, *NSET, *INCLUDE; every
// other keyword and its data lines are skipped. Keywords, parameters and set names are
// case-insensitive (sets are reported under the spelling of their first appearance).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>
#include <string_view>

#include "io/readers/ReadMesh.h"
#include "io/readers/Scanner.h"
#include "io/readers/TagIndex.h"
#include "mesher/core/Error.h"

namespace aniso::io {
namespace {

constexpr int kMaxIncludeDepth = 8;
/// A *ELSET/*NSET GENERATE range longer than this is taken for garbage, not expanded.
constexpr long long kMaxGenerated = 20000000;

std::string upper(std::string_view s) {
  std::string u(s);
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return u;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> splitCommas(std::string_view line) {
  std::vector<std::string_view> out;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

/// The element type of an Abaqus / CalculiX element name, by family and node count.
bool abaqusType(const std::string& name, CellType& out) {
  static const std::map<std::string, CellType> special = {
      {"STRI3", CellType::Triangle}, {"STRI65", CellType::Triangle6}, {"B31", CellType::Line},
      {"B32", CellType::Line3},      {"B21", CellType::Line},         {"B22", CellType::Line3}};
  if (const auto it = special.find(name); it != special.end()) {
    out = it->second;
    return true;
  }
  std::size_t i = 0;
  while (i < name.size() && std::isalpha(static_cast<unsigned char>(name[i]))) ++i;
  std::string family = name.substr(0, i);
  if (i + 1 < name.size() && name[i + 1] == 'D' && (name[i] == '2' || name[i] == '3')) {  // C3D, DC2D, M3D, ...
    family += name.substr(i, 2);
    i += 2;
  }
  std::size_t j = i;
  while (j < name.size() && std::isdigit(static_cast<unsigned char>(name[j]))) ++j;
  if (j == i) return false;
  const int n = std::stoi(name.substr(i, j - i));
  const bool solid = family == "C3D" || family == "DC3D";
  const bool face = family == "S" || family == "CPS" || family == "CPE" || family == "CAX" || family == "CPEG" ||
                    family == "M3D" || family == "R3D" || family == "DC2D" || family == "DS" || family == "SFM3D";
  const bool line = family == "T3D" || family == "T2D";
  if (solid) {
    static const std::map<int, CellType> m = {{4, CellType::Tet},   {10, CellType::Tet10},  {8, CellType::Hex},
                                              {20, CellType::Hex20}, {27, CellType::Hex27}, {6, CellType::Prism},
                                              {15, CellType::Prism15}, {5, CellType::Pyramid}};
    if (const auto it = m.find(n); it != m.end()) return out = it->second, true;
  } else if (face) {
    static const std::map<int, CellType> m = {{3, CellType::Triangle}, {6, CellType::Triangle6}, {4, CellType::Quad},
                                              {8, CellType::Quad8},    {9, CellType::Quad9}};
    if (const auto it = m.find(n); it != m.end()) return out = it->second, true;
  } else if (line && (n == 2 || n == 3)) {
    out = n == 2 ? CellType::Line : CellType::Line3;
    return true;
  }
  return false;
}

struct Keyword {
  std::string name;                          ///< upper case
  std::map<std::string, std::string> param;  ///< upper-case keys; values as written
};

Keyword parseKeyword(std::string_view line) {
  const std::vector<std::string_view> parts = splitCommas(line.substr(1));
  Keyword k{upper(parts[0]), {}};
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const std::size_t eq = parts[i].find('=');
    if (eq == std::string_view::npos) k.param[upper(parts[i])] = "";
    else k.param[upper(trim(parts[i].substr(0, eq)))] = std::string(trim(parts[i].substr(eq + 1)));
  }
  return k;
}

class InpParser {
 public:
  void file(const std::string& path, int depth);
  ReadMesh finish(const std::string& path);

 private:
  struct Set {
    std::string name;
    std::vector<long long> ids;
    std::vector<std::string> sets;  ///< sets included by name (upper case)
  };
  Set& set(std::map<std::string, Set>& sets, const std::string& name) {
    Set& s = sets[upper(name)];
    if (s.name.empty()) s.name = name;
    return s;
  }
  void setLine(Set& s, const std::vector<std::string_view>& items, bool generate, const std::string& where);

  std::vector<long long> nodeIds_, elementIds_, connIds_;
  std::vector<Vec3> nodes_;
  std::vector<CellType> types_;
  std::map<std::string, Set> elsets_, nsets_;
  std::vector<std::string> elsetOrder_, nsetOrder_;
};

void InpParser::setLine(Set& s, const std::vector<std::string_view>& items, bool generate, const std::string& where) {
  std::vector<long long> v;
  for (std::string_view it : items) {
    if (it.empty()) continue;
    long long x = 0;
    if (parseInteger(it, x)) v.push_back(x);
    else if (generate) throw InputError(where + ": GENERATE expects numbers, found '" + std::string(it) + "'");
    else s.sets.push_back(upper(it));
  }
  if (!generate) {
    s.ids.insert(s.ids.end(), v.begin(), v.end());
    return;
  }
  if (v.size() < 2 || v.size() > 3) throw InputError(where + ": GENERATE expects first, last[, step]");
  const long long step = v.size() == 3 ? v[2] : 1;
  if (step <= 0 || v[1] < v[0] || (v[1] - v[0]) / step > kMaxGenerated) throw InputError(where + ": bad GENERATE range");
  for (long long x = v[0]; x <= v[1]; x += step) s.ids.push_back(x);
}

void InpParser::file(const std::string& path, int depth) {
  const std::string data = readWholeFile(path);
  Scanner lines(data, path);
  enum class Mode { Skip, Node, Element, Elset, Nset } mode = Mode::Skip;
  CellType type = CellType::Tet;
  Set* current = nullptr;
  bool generate = false;
  std::vector<long long> pending;  ///< an element whose node list continues on the next line
  long long lineNo = 0;
  bool sawKeyword = false;
  while (!lines.atEnd()) {
    const std::string_view line = trim(lines.line());
    ++lineNo;
    const std::string where = path + ": line " + std::to_string(lineNo);
    if (line.empty() || line.substr(0, 2) == "**") continue;
    if (line.front() == '*') {
      if (!pending.empty()) throw InputError(where + ": element " + std::to_string(pending[0]) + " has too few nodes");
      sawKeyword = true;
      const Keyword k = parseKeyword(line);
      mode = Mode::Skip;
      generate = k.param.count("GENERATE") > 0;
      if (k.name == "NODE") {
        mode = Mode::Node;
        if (k.param.count("NSET")) nsetOrder_.push_back(upper(k.param.at("NSET")));
        current = k.param.count("NSET") ? &set(nsets_, k.param.at("NSET")) : nullptr;
      } else if (k.name == "ELEMENT") {
        const auto t = k.param.find("TYPE");
        if (t == k.param.end()) throw InputError(where + ": *ELEMENT without TYPE=");
        if (!abaqusType(upper(t->second), type)) throw InputError(where + ": unsupported element type " + t->second);
        mode = Mode::Element;
        current = k.param.count("ELSET") ? &set(elsets_, k.param.at("ELSET")) : nullptr;
        if (current) elsetOrder_.push_back(upper(k.param.at("ELSET")));
      } else if (k.name == "ELSET" || k.name == "NSET") {
        const bool el = k.name == "ELSET";
        const auto n = k.param.find(k.name);
        if (n == k.param.end()) throw InputError(where + ": *" + k.name + " without " + k.name + "=");
        current = &set(el ? elsets_ : nsets_, n->second);
        (el ? elsetOrder_ : nsetOrder_).push_back(upper(n->second));
        mode = el ? Mode::Elset : Mode::Nset;
      } else if (k.name == "INCLUDE") {
        const auto in = k.param.find("INPUT");
        if (in == k.param.end()) throw InputError(where + ": *INCLUDE without INPUT=");
        if (depth >= kMaxIncludeDepth) throw InputError(where + ": *INCLUDE nested too deep");
        std::string target = in->second;
        if (target.size() >= 2 && target.front() == '"' && target.back() == '"') target = target.substr(1, target.size() - 2);
        std::filesystem::path p(target);
        if (p.is_relative()) p = std::filesystem::path(path).parent_path() / p;
        file(p.string(), depth + 1);
      }
      continue;
    }
    if (!sawKeyword) throw InputError(path + ": not an Abaqus/CalculiX input deck (data before any *keyword)");
    const std::vector<std::string_view> items = splitCommas(line);
    if (mode == Mode::Node) {
      double x[3] = {0, 0, 0};
      long long id = 0;
      if (items.size() < 3 || !parseInteger(items[0], id)) throw InputError(where + ": bad *NODE line");
      for (std::size_t k = 1; k < items.size() && k <= 3; ++k)
        if (!items[k].empty() && !parseReal(items[k], x[k - 1])) throw InputError(where + ": bad coordinate");
      nodeIds_.push_back(id);
      nodes_.emplace_back(x[0], x[1], x[2]);
      if (current) current->ids.push_back(id);
    } else if (mode == Mode::Element) {
      for (std::string_view it : items) {
        if (it.empty()) continue;
        long long v = 0;
        if (!parseInteger(it, v)) throw InputError(where + ": bad *ELEMENT entry '" + std::string(it) + "'");
        pending.push_back(v);
      }
      const std::size_t need = 1 + static_cast<std::size_t>(cellNodeCount(type));
      if (pending.size() > need) throw InputError(where + ": element " + std::to_string(pending[0]) + " has too many nodes");
      if (pending.size() < need) continue;
      elementIds_.push_back(pending[0]);
      types_.push_back(type);
      connIds_.insert(connIds_.end(), pending.begin() + 1, pending.end());
      if (current) current->ids.push_back(pending[0]);
      pending.clear();
    } else if (mode == Mode::Elset || mode == Mode::Nset) {
      setLine(*current, items, generate, where);
    }
  }
  if (!pending.empty()) throw InputError(path + ": element " + std::to_string(pending[0]) + " has too few nodes");
  if (!sawKeyword) throw InputError(path + ": not an Abaqus/CalculiX input deck (no *keyword)");
}

ReadMesh InpParser::finish(const std::string& path) {
  ReadMesh m;
  m.format = "inp";
  TagIndex nodes, elements;
  if (!nodes.build(nodeIds_)) throw InputError(path + ": a node number is defined twice");
  if (!elements.build(elementIds_)) throw InputError(path + ": an element number is defined twice");
  m.nodes = std::move(nodes_);
  m.types = std::move(types_);
  std::size_t at = 0;
  for (CellType t : m.types) {
    for (int k = 0; k < cellNodeCount(t); ++k) {
      const int i = nodes.find(connIds_[at++]);
      if (i < 0) throw InputError(path + ": an element refers to node " + std::to_string(connIds_[at - 1]) + ", which is not defined");
      m.conn.push_back(i);
    }
    m.offsets.push_back(static_cast<int>(m.conn.size()));
  }
  // Sets in order of first appearance; names may include other sets (resolved one level
  // at a time, at most as many levels as there are sets).
  auto resolve = [&](std::map<std::string, Set>& sets, const std::vector<std::string>& order, const TagIndex& index,
                     const char* what, auto&& add) {
    std::vector<std::string> seen;
    for (const std::string& key : order) {
      if (std::find(seen.begin(), seen.end(), key) != seen.end()) continue;
      seen.push_back(key);
      std::vector<int> members;
      std::vector<std::string> todo = {key}, done;
      while (!todo.empty()) {
        const std::string k = todo.back();
        todo.pop_back();
        if (std::find(done.begin(), done.end(), k) != done.end()) continue;
        done.push_back(k);
        const auto it = sets.find(k);
        if (it == sets.end()) throw InputError(path + ": set " + k + " is used but not defined");
        for (long long id : it->second.ids) {
          const int i = index.find(id);
          if (i < 0) throw InputError(path + ": set " + it->second.name + " names " + what + " " + std::to_string(id) + ", which is not defined");
          members.push_back(i);
        }
        todo.insert(todo.end(), it->second.sets.begin(), it->second.sets.end());
      }
      std::sort(members.begin(), members.end());
      members.erase(std::unique(members.begin(), members.end()), members.end());
      add(sets.at(key).name, std::move(members));
    }
  };
  resolve(elsets_, elsetOrder_, elements, "element", [&](const std::string& n, std::vector<int> c) {
    m.groups.push_back({n, std::move(c)});
  });
  resolve(nsets_, nsetOrder_, nodes, "node", [&](const std::string& n, std::vector<int> c) {
    m.nodeSets.push_back({n, std::move(c)});
  });
  return m;
}

}  // namespace

ReadMesh readInp(const std::string& path) {
  InpParser p;
  p.file(path, 0);
  return p.finish(path);
}

}  // namespace aniso::io
