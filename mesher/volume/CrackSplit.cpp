#include "mesher/volume/CrackSplit.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

#include "mesher/predicates/Predicates.h"

namespace aniso {
namespace {

using Key = std::array<int, 3>;

Key sorted(const std::array<int, 3>& t) {
  Key k = t;
  std::sort(k.begin(), k.end());
  return k;
}

/// A surface triangle as a face of one tetrahedron: the tet and, per triangle corner, the
/// tet's local index of that node (valid after the tet's nodes are renamed).
struct FaceOf {
  int tet = -1;
  std::array<int, 3> local{};
};

FaceOf faceOf(const VolumeMesh& mesh, int tet, const std::array<int, 3>& tri) {
  FaceOf f;
  f.tet = tet;
  for (int k = 0; k < 3; ++k)
    f.local[k] = static_cast<int>(std::find(mesh.tets[tet].begin(), mesh.tets[tet].end(), tri[k]) - mesh.tets[tet].begin());
  return f;
}

/// Is tet t on the side the triangle's normal points to (exact)?
bool onFrontSide(const VolumeMesh& mesh, int t, const std::array<int, 3>& tri) {
  const auto& p = mesh.surface.nodes;
  for (const int v : mesh.tets[t])
    if (v != tri[0] && v != tri[1] && v != tri[2])
      return predicates::orient3d(p[tri[0]].data(), p[tri[1]].data(), p[tri[2]].data(), p[v].data()) > 0;
  return false;
}

int findRoot(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

/// A solid's crack triangles (surface indices) and faces, and the nodes of its front: the
/// crack edges used by one crack triangle and by no boundary face of the solid.
struct CrackFront {
  std::vector<int> triangles;
  std::set<int> faces;
  std::set<int> frontNodes;
  std::set<std::pair<int, int>> frontEdges;
};

CrackFront crackFront(const Model& model, int solid, const std::vector<char>& isCrack, const SurfaceMesh& sm) {
  CrackFront cf;
  for (std::size_t t = 0; t < sm.triangles.size(); ++t) {
    const int f = sm.triangleFace[t];
    if (f >= 0 && static_cast<std::size_t>(f) < isCrack.size() && isCrack[f]) {
      cf.triangles.push_back(static_cast<int>(t));
      cf.faces.insert(f);
    }
  }
  if (cf.triangles.empty()) return cf;
  std::vector<char> bounding(model.faces.size(), 0);
  for (const int f : model.solidFaces(solid))
    if (f >= 0 && static_cast<std::size_t>(f) < bounding.size()) bounding[f] = 1;
  std::map<std::pair<int, int>, std::pair<int, bool>> edges;  // -> (crack uses, on the boundary)
  for (const int t : cf.triangles)
    for (int k = 0; k < 3; ++k) ++edges[std::minmax(sm.triangles[t][k], sm.triangles[t][(k + 1) % 3])].first;
  for (std::size_t t = 0; t < sm.triangles.size(); ++t) {
    const int f = sm.triangleFace[t];
    if (f < 0 || static_cast<std::size_t>(f) >= bounding.size() || !bounding[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const auto it = edges.find(std::minmax(sm.triangles[t][k], sm.triangles[t][(k + 1) % 3]));
      if (it != edges.end()) it->second.second = true;
    }
  }
  for (const auto& [e, use] : edges)
    if (use.first == 1 && !use.second) {
      cf.frontEdges.insert(e);
      cf.frontNodes.insert({e.first, e.second});
    }
  return cf;
}

std::vector<char> faceFlags(const Model& model, const std::vector<int>& faces) {
  std::vector<char> on(model.faces.size(), 0);
  for (const int f : faces)
    if (f >= 0 && static_cast<std::size_t>(f) < on.size()) on[f] = 1;
  return on;
}

class SolidCracks {
 public:
  SolidCracks(const Model& model, int solid, const std::vector<int>& crackFaces, VolumeMesh& mesh)
      : model_(model), solid_(solid), mesh_(mesh), isCrack_(faceFlags(model, crackFaces)) {}

  void run(CrackSplitStats& st) {
    const SurfaceMesh& sm = mesh_.surface;
    const CrackFront cf = crackFront(model_, solid_, isCrack_, sm);
    crackTris_ = cf.triangles;
    if (crackTris_.empty()) return;
    for (const int t : crackTris_) crackOf_.emplace(sorted(sm.triangles[t]), t);
    st.crackFaces += static_cast<int>(cf.faces.size());
    st.faces.insert(st.faces.end(), cf.faces.begin(), cf.faces.end());
    const std::set<int>& front = cf.frontNodes;
    for (const int t : crackTris_)
      for (const int n : sm.triangles[t])
        if (!front.count(n)) split_.insert(n);
    for (std::size_t t = 0; t < mesh_.tets.size(); ++t)
      if (mesh_.tetSolid[t] != solid_)
        for (const int v : mesh_.tets[t]) split_.erase(v);
    if (split_.empty()) return;
    for (std::size_t t = 0; t < mesh_.tets.size(); ++t)
      if (mesh_.tetSolid[t] == solid_)
        for (const int v : mesh_.tets[t])
          if (split_.count(v)) around_[v].push_back(static_cast<int>(t));
    locateSurface();
    for (const auto& [n, tets] : around_) st.nodesDuplicated += splitNode(n, tets);
    renameSurface(st);
  }

 private:
  /// Every surface triangle through a node to split (crack ones on both sides), as faces
  /// of this solid's tets, recorded before any renaming.
  void locateSurface() {
    const SurfaceMesh& sm = mesh_.surface;
    std::map<Key, std::vector<int>> tetsOfFace;
    for (const auto& [n, tets] : around_)
      for (const int t : tets)
        for (int i = 0; i < 4; ++i) {
          Key k;
          for (int j = 0, m = 0; j < 4; ++j)
            if (j != i) k[m++] = mesh_.tets[t][j];
          if (std::find(k.begin(), k.end(), n) == k.end()) continue;
          std::vector<int>& list = tetsOfFace[sorted(k)];
          if (std::find(list.begin(), list.end(), t) == list.end()) list.push_back(t);
        }
    for (std::size_t t = 0; t < sm.triangles.size(); ++t) {
      const auto& tri = sm.triangles[t];
      if (!split_.count(tri[0]) && !split_.count(tri[1]) && !split_.count(tri[2])) continue;
      const auto it = tetsOfFace.find(sorted(tri));
      if (it == tetsOfFace.end()) continue;  // a face of another solid
      const int f = sm.triangleFace[t];
      if (isCrack_[f]) {
        for (const int tet : it->second)
          (onFrontSide(mesh_, tet, tri) ? crackFront_ : crackBack_)[static_cast<int>(t)] = faceOf(mesh_, tet, tri);
      } else if (it->second.size() == 1) {
        boundary_[static_cast<int>(t)] = faceOf(mesh_, it->second.front(), tri);
      }
    }
  }

  /// Groups the tets around n (connected through non-crack faces through n); the first group
  /// with a tet behind a crack triangle keeps n, the others get copies. Returns the copies.
  int splitNode(int n, const std::vector<int>& tets) {
    const std::size_t nt = tets.size();
    std::vector<int> parent(nt);
    std::iota(parent.begin(), parent.end(), 0);
    std::map<Key, int> firstWith;  // face through n -> first local tet
    std::vector<char> behind(nt, 0);
    for (std::size_t a = 0; a < nt; ++a) {
      const auto& q = mesh_.tets[tets[a]];
      for (int i = 0; i < 4; ++i) {
        if (q[i] == n) continue;
        Key k;
        for (int j = 0, m = 0; j < 4; ++j)
          if (j != i) k[m++] = q[j];
        const Key key = sorted(k);
        if (const auto c = crackOf_.find(key); c != crackOf_.end()) {
          // behind the crack triangle as the surface orients it
          if (!onFrontSide(mesh_, tets[a], mesh_.surface.triangles[c->second])) behind[a] = 1;
          continue;
        }
        const auto [it, fresh] = firstWith.emplace(key, static_cast<int>(a));
        if (!fresh) parent[findRoot(parent, static_cast<int>(a))] = findRoot(parent, it->second);
      }
    }
    // Groups in order of their first tet (tets are in increasing index order).
    std::vector<int> groupOf(nt, -1), rootGroup(nt, -1);
    int groups = 0;
    for (std::size_t a = 0; a < nt; ++a) {
      const int r = findRoot(parent, static_cast<int>(a));
      if (rootGroup[r] < 0) rootGroup[r] = groups++;
      groupOf[a] = rootGroup[r];
    }
    if (groups < 2) return 0;
    int keeper = 0;
    for (std::size_t a = 0; a < nt; ++a)
      if (behind[a]) {
        keeper = groupOf[a];
        break;
      }
    std::vector<int> copyOf(static_cast<std::size_t>(groups), n);
    for (int g = 0; g < groups; ++g) {
      if (g == keeper) continue;
      copyOf[g] = static_cast<int>(mesh_.surface.nodes.size());
      mesh_.surface.addNode(mesh_.surface.nodes[n], mesh_.surface.nodeOn[n]);
    }
    for (std::size_t a = 0; a < nt; ++a)
      for (int& v : mesh_.tets[tets[a]])
        if (v == n) v = copyOf[groupOf[a]];
    return groups - 1;
  }

  std::array<int, 3> nodesOf(const FaceOf& f) const {
    return {mesh_.tets[f.tet][f.local[0]], mesh_.tets[f.tet][f.local[1]], mesh_.tets[f.tet][f.local[2]]};
  }

  void renameSurface(CrackSplitStats& st) {
    SurfaceMesh& sm = mesh_.surface;
    for (const auto& [t, f] : boundary_) sm.triangles[t] = nodesOf(f);
    for (const auto& [t, f] : crackBack_) sm.triangles[t] = nodesOf(f);
    for (const auto& [t, f] : crackFront_) {
      const std::array<int, 3> front = nodesOf(f);
      if (sorted(front) == sorted(sm.triangles[t])) continue;  // not separated here (front only)
      sm.triangles.push_back({front[0], front[2], front[1]});
      sm.triangleFace.push_back(sm.triangleFace[t]);
      ++st.trianglesAdded;
    }
  }

  const Model& model_;
  int solid_;
  VolumeMesh& mesh_;
  std::vector<char> isCrack_;
  std::vector<int> crackTris_;
  std::map<Key, int> crackOf_;  // sorted crack triangle -> surface triangle
  std::set<int> split_;
  std::map<int, std::vector<int>> around_;                   // node -> its tets in the solid
  std::map<int, FaceOf> boundary_, crackFront_, crackBack_;  // surface triangle -> face of a tet
};

}  // namespace

CrackSplitStats splitCracks(const Model& model, const std::vector<std::vector<int>>& cracks, VolumeMesh& mesh) {
  CrackSplitStats st;
  for (std::size_t s = 0; s < cracks.size() && s < model.solids.size(); ++s)
    if (!cracks[s].empty()) SolidCracks(model, static_cast<int>(s), cracks[s], mesh).run(st);
  return st;
}

std::vector<std::array<int, 2>> crackEdgesToOpen(const Model& model, const std::vector<std::vector<int>>& cracks,
                                                 const SurfaceMesh& surface) {
  std::vector<std::array<int, 2>> out;
  for (std::size_t s = 0; s < cracks.size() && s < model.solids.size(); ++s) {
    if (cracks[s].empty()) continue;
    const CrackFront cf = crackFront(model, static_cast<int>(s), faceFlags(model, cracks[s]), surface);
    for (const int t : cf.triangles) {
      const auto& tri = surface.triangles[t];
      if (!cf.frontNodes.count(tri[0]) || !cf.frontNodes.count(tri[1]) || !cf.frontNodes.count(tri[2])) continue;
      double best = -1;
      std::array<int, 2> edge{-1, -1};
      for (int k = 0; k < 3; ++k) {
        const int a = tri[k], b = tri[(k + 1) % 3];
        if (cf.frontEdges.count(std::minmax(a, b))) continue;
        const double l = (surface.nodes[a] - surface.nodes[b]).squaredNorm();
        if (l > best) best = l, edge = {a, b};
      }
      if (edge[0] >= 0) out.push_back(edge);
    }
  }
  return out;
}

}  // namespace aniso
