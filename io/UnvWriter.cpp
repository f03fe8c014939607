// I-DEAS universal file (.unv) writer: datasets 2411 (nodes), 2412 (elements) and 2467
// (permanent groups), laid out as Gmsh writes them, which is what FreeCAD's FEM importer
// (SMESH's DriverUNV) and Gmsh itself read. Elements: the triangles and quads (thin shell
// 91/92, 94/95) numbered first, then the tetrahedra (111/118); fields 3 and 4 of each
// element record (physical and material property tables) hold its face or solid id, which
// Gmsh reads as its elementary and physical tags. Groups: per meshed face "FACE<n>" (its
// nodes, then its elements), then per solid its part name (its tetrahedra), then per named
// face group (groupNames) its faces' nodes and elements.
#include <algorithm>
#include <cstdio>
#include <ostream>
#include <vector>

#include "io/AtomicFile.h"
#include "io/ElementOrder.h"
#include "io/FormatWriters.h"

namespace aniso::io {
namespace {

int unvType(Shape s, bool quadratic) {
  switch (s) {
    case Shape::Triangle: return quadratic ? 92 : 91;
    case Shape::Quad: return quadratic ? 95 : 94;
    case Shape::Tet: return quadratic ? 118 : 111;
  }
  return 0;
}

const int* unvOrder(Shape s, bool quadratic) {
  if (!quadratic) return order::kIdentity.data();
  switch (s) {
    case Shape::Triangle: return order::kUnvTri6.data();
    case Shape::Quad: return order::kUnvQuad8.data();
    case Shape::Tet: return order::kUnvTet10.data();
  }
  return order::kIdentity.data();
}

void writeNodes(std::ostream& o, const std::vector<Vec3>& p) {
  o << "    -1\n  2411\n";
  char buf[128];
  for (size_t i = 0; i < p.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%10zu%10d%10d%10d\n", i + 1, 1, 1, 11);
    o << buf;
    std::snprintf(buf, sizeof buf, "%25.16E%25.16E%25.16E\n", p[i].x(), p[i].y(), p[i].z());
    for (char* c = buf; *c; ++c)
      if (*c == 'E') *c = 'D';  // FORTRAN double precision exponents
    o << buf;
  }
  o << "    -1\n";
}

/// One group record: entities as (type code, label) pairs, two per line.
void writeGroup(std::ostream& o, int id, const std::string& name, const std::vector<long long>& nodes,
                const std::vector<long long>& elements) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%10d%10d%10d%10d%10d%10d%10d%10zu\n", id, 0, 0, 0, 0, 0, 0,
                nodes.size() + elements.size());
  o << buf << name << '\n';
  int row = 0;
  auto put = [&](int code, long long label) {
    if (row == 2) {
      o << '\n';
      row = 0;
    }
    std::snprintf(buf, sizeof buf, "%10d%10lld%10d%10d", code, label, 0, 0);
    o << buf;
    ++row;
  };
  for (long long n : nodes) put(7, n);
  for (long long e : elements) put(8, e);
  o << '\n';
}

}  // namespace

void writeUnv(const OutputMesh& m, const std::string& path) {
  AtomicFile file(path);
  std::ostream& o = file.stream();
  writeNodes(o, m.nodes());

  // Elements, numbered from 1 in the order triangles, quads, tetrahedra.
  o << "    -1\n  2412\n";
  std::vector<std::vector<long long>> faceElements(m.model.faces.size()), solidElements(m.model.solids.size());
  std::vector<std::vector<long long>> faceNodes(m.model.faces.size());
  std::array<int, 10> nodes{};
  char buf[128];
  long long label = 1;
  for (Shape s : {Shape::Triangle, Shape::Quad, Shape::Tet}) {
    const bool q = m.quadratic(s);
    const int type = unvType(s, q);
    const int* perm = unvOrder(s, q);
    for (int i = 0, n = m.count(s); i < n; ++i) {
      const int k = m.elementNodes(s, i, nodes);
      const int entity = m.entityOf(s, i);
      std::snprintf(buf, sizeof buf, "%10lld%10d%10d%10d%10d%10d\n", label, type, entity + 1, entity + 1, 7, k);
      o << buf;
      for (int j = 0; j < k; ++j) {
        std::snprintf(buf, sizeof buf, "%10d", nodes[perm[j]] + 1);
        o << buf << (j % 8 == 7 || j + 1 == k ? "\n" : "");
      }
      if (s == Shape::Tet) {
        solidElements[entity].push_back(label);
      } else {
        faceElements[entity].push_back(label);
        for (int j = 0; j < k; ++j) faceNodes[entity].push_back(nodes[j] + 1);
      }
      ++label;
    }
  }
  o << "    -1\n";

  o << "    -1\n  2467\n";
  int group = 1;
  for (size_t f = 0; f < faceElements.size(); ++f) {
    if (faceElements[f].empty()) continue;
    std::vector<long long>& fn = faceNodes[f];
    std::sort(fn.begin(), fn.end());
    fn.erase(std::unique(fn.begin(), fn.end()), fn.end());
    writeGroup(o, group++, "FACE" + std::to_string(f + 1), fn, faceElements[f]);
  }
  const GroupNames names = groupNames(m.model);
  for (size_t s = 0; s < solidElements.size(); ++s)
    if (!solidElements[s].empty()) writeGroup(o, group++, names.solids[s], {}, solidElements[s]);
  for (const FaceGroup& g : names.faces) {  // after the others: a model without them is unchanged
    const std::vector<long long> ge = groupIds(g, faceElements);
    if (!ge.empty()) writeGroup(o, group++, g.name, groupIds(g, faceNodes), ge);
  }
  o << "    -1\n";
  file.commit();
}

}  // namespace aniso::io
