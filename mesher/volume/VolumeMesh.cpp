#include "mesher/volume/VolumeMesh.h"

#include <algorithm>
#include <map>
#include <set>

#include "mesher/predicates/Predicates.h"

namespace aniso {

std::vector<std::string> VolumeMesh::validate() const {
  std::vector<std::string> problems;
  const auto& p = nodes();
  const int n = static_cast<int>(p.size());
  if (tetSolid.size() != tets.size()) problems.push_back("tetSolid has " + std::to_string(tetSolid.size()) +
                                                         " entries for " + std::to_string(tets.size()) + " tetrahedra");
  using Key = std::array<int, 3>;
  std::map<Key, int> faceUses;
  std::set<std::array<int, 4>> seen;
  long long badIndex = 0, nonPositive = 0, repeated = 0;
  for (const auto& t : tets) {
    if (std::any_of(t.begin(), t.end(), [&](int v) { return v < 0 || v >= n; })) {
      ++badIndex;
      continue;
    }
    if (predicates::orient3d(p[t[0]].data(), p[t[1]].data(), p[t[2]].data(), p[t[3]].data()) <= 0) ++nonPositive;
    std::array<int, 4> s = t;
    std::sort(s.begin(), s.end());
    if (!seen.insert(s).second) ++repeated;
    for (int i = 0; i < 4; ++i) {
      Key k;
      for (int j = 0, m = 0; j < 4; ++j)
        if (j != i) k[m++] = t[j];
      std::sort(k.begin(), k.end());
      ++faceUses[k];
    }
  }
  std::set<Key> boundary;
  for (const auto& tri : surface.triangles) {
    Key k = tri;
    std::sort(k.begin(), k.end());
    boundary.insert(k);
  }
  for (const auto& tri : patchFaces) {
    Key k = tri;
    std::sort(k.begin(), k.end());
    boundary.insert(k);
  }
  long long overUsed = 0, openFaces = 0;
  for (const auto& [k, uses] : faceUses) {
    if (uses > 2) ++overUsed;
    if (uses == 1 && !boundary.count(k)) ++openFaces;
  }
  if (badIndex) problems.push_back(std::to_string(badIndex) + " tetrahedra with node indices out of range");
  if (nonPositive) problems.push_back(std::to_string(nonPositive) + " tetrahedra not positively oriented");
  if (repeated) problems.push_back(std::to_string(repeated) + " repeated tetrahedra");
  if (overUsed) problems.push_back(std::to_string(overUsed) + " faces shared by more than two tetrahedra");
  if (openFaces) problems.push_back(std::to_string(openFaces) + " faces used by one tetrahedron are not boundary triangles");
  return problems;
}

}  // namespace aniso
