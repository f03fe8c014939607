#include "io/readers/fields/MshData.h"

#include <limits>

namespace aniso::io {
namespace {

/// Gmsh allows 1, 3 or 9 components; anything far above is garbage.
constexpr long long kMaxComponents = 81;

}  // namespace

MshDataSection readMshDataSection(Scanner& s, bool binary, bool element) {
  MshDataSection out;
  out.element = element;
  const long long nStrings = s.integer();
  if (nStrings < 0 || nStrings > 1000) s.fail("implausible string tag count");
  s.line();  // rest of the count line
  for (long long i = 0; i < nStrings; ++i) {
    std::string_view t = s.line();
    while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
    while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.remove_suffix(1);
    if (t.size() >= 2 && t.front() == '"' && t.back() == '"') t = t.substr(1, t.size() - 2);
    if (i == 0) out.name = std::string(t);
  }
  const long long nReals = s.integer();
  if (nReals < 0 || nReals > 1000) s.fail("implausible real tag count");
  for (long long i = 0; i < nReals; ++i) s.real();
  const long long nInts = s.integer();
  if (nInts < 3 || nInts > 1000) s.fail("a data section needs 3 integer tags (step, components, count)");
  long long ints[3] = {0, 0, 0};
  for (long long i = 0; i < nInts; ++i) {
    const long long v = s.integer();
    if (i < 3) ints[i] = v;
  }
  if (ints[1] < 1 || ints[1] > kMaxComponents) s.fail("implausible component count " + std::to_string(ints[1]));
  out.components = static_cast<int>(ints[1]);
  const long long n = ints[2];
  if (n < 0 || n > 1'000'000'000) s.fail("implausible data count " + std::to_string(n));
  out.tags.reserve(static_cast<std::size_t>(n));
  out.values.reserve(static_cast<std::size_t>(n) * out.components);
  if (binary) s.skipNewline();
  for (long long i = 0; i < n; ++i) {
    out.tags.push_back(binary ? s.binary<std::int32_t>() : s.integer());
    for (int c = 0; c < out.components; ++c) out.values.push_back(binary ? s.binary<double>() : s.real());
  }
  s.expect(element ? "$EndElementData" : "$EndNodeData");
  return out;
}

std::vector<MeshData> mshDataArrays(const std::vector<MshDataSection>& sections, bool element, const TagIndex& index,
                                    std::size_t count, Scanner& s) {
  std::vector<MeshData> out;
  for (const MshDataSection& sec : sections) {
    if (sec.element != element) continue;
    MeshData* d = nullptr;
    for (MeshData& o : out)
      if (o.name == sec.name) d = &o;
    if (!d) d = &out.emplace_back();
    d->name = sec.name;
    d->components = sec.components;
    d->values.assign(count * sec.components, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < sec.tags.size(); ++i) {
      const int at = index.find(sec.tags[i]);
      if (at < 0)
        s.fail(std::string(element ? "$ElementData" : "$NodeData") + " '" + sec.name + "' refers to " +
               (element ? "element " : "node ") + std::to_string(sec.tags[i]) + ", which is not defined");
      for (int c = 0; c < sec.components; ++c) d->values[at * sec.components + c] = sec.values[i * sec.components + c];
    }
  }
  return out;
}

}  // namespace aniso::io
