#include "io/readers/fields/NodalField.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>

#include <Eigen/Eigenvalues>

#include "io/readers/Scanner.h"
#include "mesher/core/Error.h"

namespace aniso::io {
namespace {

bool sameIgnoringCase(const std::string& a, const std::string& b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return std::tolower(x) == std::tolower(y); });
}

std::string available(const ReadMesh& m) {
  std::string out;
  for (const auto* list : {&m.pointData, &m.cellData})
    for (const MeshData& d : *list) {
      if (!out.empty()) out += ", ";
      out += d.name + (d.components > 1 ? " (" + std::to_string(d.components) + ")" : "");
    }
  return out;
}

const MeshData* findArray(const std::vector<MeshData>& list, const std::string& name) {
  for (const MeshData& d : list)
    if (d.name == name) return &d;
  for (const MeshData& d : list)
    if (sameIgnoringCase(d.name, name)) return &d;
  return nullptr;
}

/// The six components xx yy zz xy yz zx of a 6- or 9-component tensor.
void symmetric6(const MeshData& d, const double* v, double s6[6]) {
  if (d.components == 6) {
    std::copy(v, v + 6, s6);
    return;
  }
  s6[0] = v[0], s6[1] = v[4], s6[2] = v[8];
  s6[3] = 0.5 * (v[1] + v[3]), s6[4] = 0.5 * (v[5] + v[7]), s6[5] = 0.5 * (v[2] + v[6]);
}

using Extract = std::function<double(const double*)>;

/// The scalar one entry of `d` gives for component `comp` ("" = the default).
Extract extractor(const MeshData& d, const std::string& comp, const std::string& path) {
  const int n = d.components;
  const bool tensor = n == 6 || n == 9;
  auto fail = [&](const std::string& what) -> Extract { throw InputError(path + ": field " + d.name + ": " + what); };
  if (comp.empty()) {
    if (n == 1) return [](const double* v) { return v[0]; };
    if (n == 2 || n == 3 || n == 4)
      return [n](const double* v) {
        double s = 0;
        for (int c = 0; c < std::min(n, 3); ++c) s += v[c] * v[c];
        return std::sqrt(s);
      };
    if (tensor) return [&d](const double* v) { double s[6]; symmetric6(d, v, s); return vonMises(s); };
    return fail("has " + std::to_string(n) + " components: choose one (" + d.name + ":0 ...)");
  }
  for (int c = 0; c < static_cast<int>(d.componentNames.size()); ++c)
    if (sameIgnoringCase(d.componentNames[c], comp)) return [c](const double* v) { return v[c]; };
  long long index = -1;
  if (parseInteger(comp, index)) {
    if (index < 0 || index >= n) return fail("no component " + comp + " (it has " + std::to_string(n) + ")");
    return [index](const double* v) { return v[index]; };
  }
  std::string c = comp;
  std::transform(c.begin(), c.end(), c.begin(), [](unsigned char x) { return static_cast<char>(std::tolower(x)); });
  if (!tensor && n <= 4 && c.size() == 1 && c[0] >= 'x' && c[0] < 'x' + std::min(n, 3)) {
    const int k = c[0] - 'x';
    return [k](const double* v) { return v[k]; };
  }
  if (tensor) {
    static const char* names[] = {"xx", "yy", "zz", "xy", "yz", "zx"};
    for (int k = 0; k < 6; ++k)
      if (c == names[k] || (k == 5 && c == "xz"))
        return [&d, k](const double* v) { double s[6]; symmetric6(d, v, s); return s[k]; };
    if (c == "mises") return [&d](const double* v) { double s[6]; symmetric6(d, v, s); return vonMises(s); };
    if (c == "p1" || c == "p2" || c == "p3") {
      const int k = c[1] - '1';
      return [&d, k](const double* v) { double s[6], p[3]; symmetric6(d, v, s); principalValues(s, p); return p[k]; };
    }
  }
  return fail("unknown component '" + comp + "'");
}

/// The value `f` gives at every node of `mesh`: from node data, or element data averaged
/// (NaN at a node no element with a finite value uses).
std::vector<double> atNodes(const ReadMesh& mesh, const MeshData& d, bool perCell, const Extract& f) {
  const std::size_t n = mesh.nodes.size();
  std::vector<double> out(n);
  if (!perCell) {
    for (std::size_t i = 0; i < n; ++i) out[i] = f(d.values.data() + i * d.components);
    return out;
  }
  std::vector<double> sum(n, 0.0);
  std::vector<int> count(n, 0);
  for (std::size_t e = 0; e < mesh.cellCount(); ++e) {
    const double v = f(d.values.data() + e * d.components);
    if (!std::isfinite(v)) continue;
    for (int k = 0; k < mesh.cellSize(e); ++k) {
      sum[mesh.cell(e)[k]] += v;
      ++count[mesh.cell(e)[k]];
    }
  }
  for (std::size_t i = 0; i < n; ++i) out[i] = count[i] ? sum[i] / count[i] : std::nan("");
  return out;
}

}  // namespace

double vonMises(const double* s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

void principalValues(const double* s, double out[3]) {
  Eigen::Matrix3d t;
  t << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  const Eigen::Vector3d e = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(t, Eigen::EigenvaluesOnly).eigenvalues();
  out[0] = e[2], out[1] = e[1], out[2] = e[0];
}

NodalField selectField(const ReadMesh& mesh, const std::string& spec, const std::string& path) {
  if (mesh.pointData.empty() && mesh.cellData.empty())
    throw InputError(path + ": no field in the file (no node or element data" +
                     (mesh.format == "frd" ? std::string(", no result blocks") : std::string()) + ")");
  std::string name = spec, comp;
  // a name may itself contain ':'; the component is what follows the last one, when the
  // whole spec is not an array's name
  const std::size_t colon = spec.rfind(':');
  if (colon != std::string::npos && !findArray(mesh.pointData, spec) && !findArray(mesh.cellData, spec)) {
    name = spec.substr(0, colon);
    comp = spec.substr(colon + 1);
  }
  const MeshData* d = findArray(mesh.pointData, name);
  const bool perCell = !d;
  if (!d) d = findArray(mesh.cellData, name);
  if (!d) throw InputError(path + ": no field '" + name + "' (the file has: " + available(mesh) + ")");
  NodalField out;
  out.name = spec;
  out.values = atNodes(mesh, *d, perCell, extractor(*d, comp, path));
  out.arrayName = d->name;
  out.components = d->components;
  const std::size_t n = mesh.nodes.size();
  out.arrayValues.resize(n * d->components);
  for (int c = 0; c < d->components; ++c) {
    const std::vector<double> v = atNodes(mesh, *d, perCell, [c](const double* x) { return x[c]; });
    for (std::size_t i = 0; i < n; ++i) out.arrayValues[i * d->components + c] = v[i];
  }
  // nodes no element uses carry no information (and may have no value)
  std::vector<char> used(n, 0);
  for (int v : mesh.conn) used[v] = 1;
  std::size_t bad = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (used[i] && !std::isfinite(out.values[i])) ++bad;
  if (bad)
    throw InputError(path + ": field '" + spec + "' is not finite (NaN, inf or no value) at " + std::to_string(bad) +
                     " of " + std::to_string(n) + " nodes");
  return out;
}

}  // namespace aniso::io
