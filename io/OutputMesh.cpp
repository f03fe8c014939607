#include "io/OutputMesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

#include "mesher/core/Error.h"
#include "mesher/metric/MeanRatio.h"

namespace aniso::io {

int OutputMesh::count(Shape s) const {
  switch (s) {
    case Shape::Triangle: return static_cast<int>(surface.triangles.size());
    case Shape::Quad: return static_cast<int>(surface.quads.size());
    case Shape::Tet: return volume ? static_cast<int>(volume->tets.size()) : 0;
  }
  return 0;
}

bool OutputMesh::quadratic(Shape s) const {
  switch (s) {
    case Shape::Triangle: return !surface.triangleMid.empty();
    case Shape::Quad: return !surface.quadMid.empty();
    case Shape::Tet: return volume && !volume->tetMid.empty();
  }
  return false;
}

int OutputMesh::nodesPer(Shape s) const {
  const bool q = quadratic(s);
  switch (s) {
    case Shape::Triangle: return q ? 6 : 3;
    case Shape::Quad: return q ? 8 : 4;
    case Shape::Tet: return q ? 10 : 4;
  }
  return 0;
}

int OutputMesh::elementNodes(Shape s, int i, std::array<int, 10>& out) const {
  int n = 0;
  auto put = [&](const auto& a) {
    for (int v : a) out[n++] = v;
  };
  switch (s) {
    case Shape::Triangle:
      put(surface.triangles[i]);
      if (quadratic(s)) put(surface.triangleMid[i]);
      break;
    case Shape::Quad:
      put(surface.quads[i]);
      if (quadratic(s)) put(surface.quadMid[i]);
      break;
    case Shape::Tet:
      put(volume->tets[i]);
      if (quadratic(s)) put(volume->tetMid[i]);
      break;
  }
  return n;
}

int OutputMesh::entityOf(Shape s, int i) const {
  switch (s) {
    case Shape::Triangle: return surface.triangleFace[i];
    case Shape::Quad: return surface.quadFace[i];
    case Shape::Tet: return volume->tetSolid[i];
  }
  return -1;
}

std::vector<std::vector<int>> OutputMesh::byEntity(Shape s) const {
  std::vector<std::vector<int>> out(s == Shape::Tet ? model.solids.size() : model.faces.size());
  for (int i = 0, n = count(s); i < n; ++i) out[entityOf(s, i)].push_back(i);
  return out;
}

std::vector<bool> OutputMesh::meshedFaces() const {
  std::vector<bool> used(model.faces.size(), false);
  for (int f : surface.triangleFace) used[f] = true;
  for (int f : surface.quadFace) used[f] = true;
  return used;
}

std::vector<bool> OutputMesh::meshedSolids() const {
  std::vector<bool> used(model.solids.size(), false);
  if (volume)
    for (int s : volume->tetSolid) used[s] = true;
  return used;
}

void OutputMesh::check(const std::string& path) const {
  auto fail = [&](const std::string& what) { throw MeshingError(path + ": cannot write the mesh: " + what); };
  const int nn = static_cast<int>(surface.nodes.size());
  if (surface.nodeOn.size() != surface.nodes.size()) fail("node classification missing");
  if (surface.triangleFace.size() != surface.triangles.size() || surface.quadFace.size() != surface.quads.size())
    fail("element faces missing");
  if (quadratic(Shape::Triangle) && surface.triangleMid.size() != surface.triangles.size())
    fail("mid-edge nodes missing on triangles");
  if (quadratic(Shape::Quad) && surface.quadMid.size() != surface.quads.size()) fail("mid-edge nodes missing on quads");
  if (volume) {
    if (volume->tetSolid.size() != volume->tets.size()) fail("tetrahedron solids missing");
    if (quadratic(Shape::Tet) && volume->tetMid.size() != volume->tets.size())
      fail("mid-edge nodes missing on tetrahedra");
  }
  for (Shape s : {Shape::Triangle, Shape::Quad, Shape::Tet}) {
    const int entities = static_cast<int>(s == Shape::Tet ? model.solids.size() : model.faces.size());
    std::array<int, 10> nodes{};
    for (int i = 0, n = count(s); i < n; ++i) {
      const int e = entityOf(s, i);
      if (e < 0 || e >= entities) fail("element on an entity outside the model");
      const int k = elementNodes(s, i, nodes);
      for (int j = 0; j < k; ++j)
        if (nodes[j] < 0 || nodes[j] >= nn) fail("element node out of range");
    }
  }
  for (const NodeOn& on : surface.nodeOn) {
    const size_t limit = on.kind == NodeOn::Kind::Vertex ? model.vertices.size()
                         : on.kind == NodeOn::Kind::Edge ? model.edges.size()
                         : on.kind == NodeOn::Kind::Face ? model.faces.size()
                                                         : model.solids.size();
    if (on.entity < 0 || static_cast<size_t>(on.entity) >= limit) fail("node on an entity outside the model");
  }
}

namespace {

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string abaqusIdentifier(const std::string& name) {
  std::string out;
  for (unsigned char c : name) out += (std::isalnum(c) || c == '_') && c < 128 ? static_cast<char>(c) : '_';
  if (out.empty() || !std::isalpha(static_cast<unsigned char>(out[0]))) out = "P_" + out;
  return out.substr(0, 64);  // CalculiX reads names of up to 80 characters; room for "_<k>"
}

/// Names the writers define: NALL, EALL, FACE<n>, S_FACE<n>, EDGE<n>.
bool reservedInAbaqus(const std::string& upperName) {
  if (upperName == "NALL" || upperName == "EALL") return true;
  for (const char* prefix : {"FACE", "S_FACE", "EDGE"}) {
    const std::string p(prefix);
    if (upperName.size() > p.size() && upperName.compare(0, p.size(), p) == 0 &&
        std::all_of(upperName.begin() + static_cast<long>(p.size()), upperName.end(),
                    [](unsigned char c) { return std::isdigit(c); }))
      return true;
  }
  return false;
}

}  // namespace

GroupNames groupNames(const Model& model) {
  GroupNames out;
  std::set<std::string> taken;  // upper case
  const auto claim = [&taken](const std::string& raw) {
    const std::string base = abaqusIdentifier(raw);
    std::string name = base;
    for (int k = 2; taken.count(upper(name)) || reservedInAbaqus(upper(name)); ++k) name = base + "_" + std::to_string(k);
    taken.insert(upper(name));
    return name;
  };
  for (size_t i = 0; i < model.solids.size(); ++i)
    out.solids.push_back(claim(model.solids[i].name.empty() ? "SOLID" + std::to_string(i + 1) : model.solids[i].name));
  std::vector<std::string> raw;  // the STEP name of each group
  for (size_t f = 0; f < model.faces.size(); ++f) {
    const std::string& name = model.faces[f].name;
    if (name.empty()) continue;
    const auto k = static_cast<size_t>(std::find(raw.begin(), raw.end(), name) - raw.begin());
    if (k == raw.size()) {
      raw.push_back(name);
      out.faces.push_back({{}, {}});
    }
    out.faces[k].faces.push_back(static_cast<int>(f));
  }
  for (size_t k = 0; k < raw.size(); ++k) out.faces[k].name = claim(raw[k]);
  return out;
}

double elementQuality(const OutputMesh& mesh, Shape s, int i) {
  const std::vector<Vec3>& p = mesh.nodes();
  switch (s) {
    case Shape::Triangle: {
      const auto& t = mesh.surface.triangles[i];
      const Vec3 a = p[t[1]] - p[t[0]], b = p[t[2]] - p[t[0]], c = p[t[2]] - p[t[1]];
      const double sum = a.squaredNorm() + b.squaredNorm() + c.squaredNorm();
      return sum > 0 ? 2 * std::sqrt(3.0) * a.cross(b).norm() / sum : 0.0;
    }
    case Shape::Quad: {
      const auto& q = mesh.surface.quads[i];
      Vec3 normal = Vec3::Zero();
      for (int k = 0; k < 4; ++k)
        normal += (p[q[(k + 1) % 4]] - p[q[k]]).cross(p[q[(k + 3) % 4]] - p[q[k]]);
      if (!(normal.norm() > 0)) return 0.0;
      normal.normalize();
      double worst = 1;
      for (int k = 0; k < 4; ++k) {
        const Vec3 e1 = p[q[(k + 1) % 4]] - p[q[k]], e2 = p[q[(k + 3) % 4]] - p[q[k]];
        const double l = e1.norm() * e2.norm();
        worst = std::min(worst, l > 0 ? e1.cross(e2).dot(normal) / l : 0.0);
      }
      return worst;
    }
    case Shape::Tet: {
      const auto& t = mesh.volume->tets[i];
      return meanRatio(p[t[0]], p[t[1]], p[t[2]], p[t[3]]);
    }
  }
  return 0.0;
}

}  // namespace aniso::io
