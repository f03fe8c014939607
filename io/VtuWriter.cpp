// VTK XML unstructured grid (.vtu) writer: ASCII, or with `binary` inline base64 data
// arrays (format="binary", header_type="UInt64": each array is base64 of its byte count
// followed by its bytes). Cells: the triangles, the quads, then the tetrahedra. Node data
// (WriteOptions::nodeData) as PointData arrays. The group names (groupNames) as FieldData,
// one Int32 array per group named after it, so that the bare integers of "region" and
// "face" can be decoded: "region:<part>" holds its region id (for every meshed solid),
// "face:<name>" the face ids of a named face group. Plain numeric arrays, since meshio
// (5.x) refuses VTK's String arrays; ParaView lists them in its Information panel.
#include <bit>
#include <cstdint>
#include <cstring>
#include <iomanip>
#include <ostream>
#include <vector>

#include "io/AtomicFile.h"
#include "io/FormatWriters.h"

namespace aniso::io {
namespace {

static_assert(std::endian::native == std::endian::little, "the binary VTU arrays are declared LittleEndian");

std::string base64(const std::vector<std::uint8_t>& in) {
  static const char* chars = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (size_t i = 0; i < in.size(); i += 3) {
    const std::uint32_t a = in[i], b = i + 1 < in.size() ? in[i + 1] : 0, c = i + 2 < in.size() ? in[i + 2] : 0;
    const std::uint32_t v = (a << 16) | (b << 8) | c;
    out += chars[(v >> 18) & 63];
    out += chars[(v >> 12) & 63];
    out += i + 1 < in.size() ? chars[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? chars[v & 63] : '=';
  }
  return out;
}

class VtuOut {
 public:
  VtuOut(std::ostream& o, bool binary) : o_(o), binary_(binary) { o_ << std::setprecision(17); }

  template <class T>
  void array(const char* type, const char* name, int components, const std::vector<T>& v) {
    o_ << "        <DataArray type=\"" << type << "\" Name=\"" << name << '"';
    if (components > 1) o_ << " NumberOfComponents=\"" << components << '"';
    o_ << " format=\"" << (binary_ ? "binary" : "ascii") << "\">\n";
    if (binary_) {
      const std::uint64_t bytes = v.size() * sizeof(T);
      std::vector<std::uint8_t> raw(sizeof bytes + bytes);
      std::memcpy(raw.data(), &bytes, sizeof bytes);
      if (bytes) std::memcpy(raw.data() + sizeof bytes, v.data(), bytes);
      o_ << "          " << base64(raw) << '\n';
    } else {
      const size_t perLine = components > 1 ? static_cast<size_t>(components) : 12;
      for (size_t i = 0; i < v.size(); ++i) {
        if (i % perLine == 0) o_ << "          ";
        if constexpr (sizeof(T) == 1)
          o_ << static_cast<int>(v[i]);
        else
          o_ << v[i];
        o_ << ((i + 1) % perLine == 0 || i + 1 == v.size() ? '\n' : ' ');
      }
    }
    o_ << "        </DataArray>\n";
  }

 private:
  std::ostream& o_;
  bool binary_;
};

/// `s` with XML's special characters as entities (an attribute value in double quotes).
std::string xmlEscaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::uint8_t vtkType(Shape s, bool quadratic) {
  switch (s) {
    case Shape::Triangle: return quadratic ? 22 : 5;
    case Shape::Quad: return quadratic ? 23 : 9;
    case Shape::Tet: return quadratic ? 24 : 10;
  }
  return 0;
}

/// The FieldData of the group names (see the top of this file); nothing without groups.
void writeGroupNames(std::ostream& o, const OutputMesh& m) {
  const GroupNames names = groupNames(m.model);
  const std::vector<bool> solids = m.meshedSolids(), faces = m.meshedFaces();
  std::vector<std::pair<std::string, std::vector<int>>> arrays;
  for (size_t s = 0; s < solids.size(); ++s)
    if (solids[s]) arrays.push_back({"region:" + names.solids[s], {static_cast<int>(s) + 1}});
  for (const FaceGroup& g : names.faces) {
    std::vector<int> ids;
    for (const int f : g.faces)
      if (faces[static_cast<size_t>(f)]) ids.push_back(f + 1);
    if (!ids.empty()) arrays.push_back({"face:" + g.name, ids});
  }
  if (arrays.empty()) return;
  o << "    <FieldData>\n";
  for (const auto& [name, ids] : arrays) {
    o << "      <DataArray type=\"Int32\" Name=\"" << xmlEscaped(name) << "\" NumberOfTuples=\"" << ids.size()
      << "\" format=\"ascii\">\n        ";
    for (size_t i = 0; i < ids.size(); ++i) o << ids[i] << (i + 1 == ids.size() ? "\n" : " ");
    o << "      </DataArray>\n";
  }
  o << "    </FieldData>\n";
}

}  // namespace

void writeVtu(const OutputMesh& m, const std::string& path, const WriteOptions& opt) {
  std::vector<double> points;
  points.reserve(m.nodes().size() * 3);
  for (const Vec3& p : m.nodes()) points.insert(points.end(), {p.x(), p.y(), p.z()});
  std::vector<std::int64_t> connectivity, offsets;
  std::vector<std::uint8_t> types;
  std::vector<std::int32_t> region, face;
  std::vector<double> quality;
  std::array<int, 10> nodes{};
  for (Shape s : {Shape::Triangle, Shape::Quad, Shape::Tet}) {
    const std::uint8_t type = vtkType(s, m.quadratic(s));
    for (int i = 0, n = m.count(s); i < n; ++i) {
      const int k = m.elementNodes(s, i, nodes);  // VTK order is our canonical order
      connectivity.insert(connectivity.end(), nodes.begin(), nodes.begin() + k);
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
      types.push_back(type);
      const int entity = m.entityOf(s, i) + 1;
      region.push_back(s == Shape::Tet ? entity : 0);
      face.push_back(s == Shape::Tet ? 0 : entity);
      quality.push_back(elementQuality(m, s, i));
    }
  }

  AtomicFile file(path);
  std::ostream& o = file.stream();
  VtuOut w(o, opt.binary);
  o << "<?xml version=\"1.0\"?>\n"
    << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
    << "  <UnstructuredGrid>\n";
  writeGroupNames(o, m);
  o << "    <Piece NumberOfPoints=\"" << m.nodes().size() << "\" NumberOfCells=\"" << types.size() << "\">\n"
    << "      <Points>\n";
  w.array("Float64", "Points", 3, points);
  o << "      </Points>\n      <Cells>\n";
  w.array("Int64", "connectivity", 1, connectivity);
  w.array("Int64", "offsets", 1, offsets);
  w.array("UInt8", "types", 1, types);
  o << "      </Cells>\n";
  if (!opt.nodeData.empty()) {
    o << "      <PointData>\n";
    for (const NodeData& d : opt.nodeData) w.array("Float64", xmlEscaped(d.name).c_str(), d.components, d.values);
    o << "      </PointData>\n";
  }
  o << "      <CellData Scalars=\"quality\">\n";
  w.array("Int32", "region", 1, region);
  w.array("Int32", "face", 1, face);
  w.array("Float64", "quality", 1, quality);
  o << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  file.commit();
}

}  // namespace aniso::io
