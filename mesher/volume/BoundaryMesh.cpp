#include "mesher/volume/BoundaryMesh.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include <Eigen/Geometry>

#include "mesher/core/Error.h"

namespace aniso {
namespace {

/// One face use of a shell, with the direction its surface-mesh triangles must take.
struct OrientedFace {
  int face;
  bool flip;  ///< reverse the surface mesh's triangles (face use opposite to the face)
};

std::array<int, 3> oriented(const std::array<int, 3>& t, bool flip) {
  return flip ? std::array<int, 3>{t[0], t[2], t[1]} : t;
}

std::string faceList(const std::set<int>& faces) {
  std::string s;
  int shown = 0;
  for (const int f : faces) {
    if (shown++ == 12) {
      s += ", ...";
      break;
    }
    s += (s.empty() ? "" : ", ") + std::to_string(f + 1);
  }
  return s;
}

/// Two triangles on the same three nodes with opposite orientations — two coincident faces
/// with the solid on both sides, sharing one mesh (contour/CoincidentFaces.h) — lie inside
/// the material: both are left out, and a face with no triangle left is internal.
void cancelOppositePairs(BoundaryMesh& b) {
  std::vector<std::pair<std::array<int, 3>, int>> sorted;  // sorted triple, triangle
  sorted.reserve(b.triangles.size());
  for (std::size_t t = 0; t < b.triangles.size(); ++t) {
    std::array<int, 3> k = b.triangles[t];
    std::sort(k.begin(), k.end());
    sorted.push_back({k, static_cast<int>(t)});
  }
  std::sort(sorted.begin(), sorted.end());
  // orientation of a triple: +1 for an even rotation of its sorted order, -1 otherwise
  const auto parity = [](const std::array<int, 3>& t) {
    const int m = static_cast<int>(std::min_element(t.begin(), t.end()) - t.begin());
    return t[(m + 1) % 3] < t[(m + 2) % 3] ? 1 : -1;
  };
  std::vector<char> drop(b.triangles.size(), 0);
  bool any = false;
  for (std::size_t i = 0; i + 1 < sorted.size(); ++i) {
    if (sorted[i].first != sorted[i + 1].first) continue;
    const bool pairOnly = (i + 2 >= sorted.size() || sorted[i + 2].first != sorted[i].first) &&
                          (i == 0 || sorted[i - 1].first != sorted[i].first);
    const int a = sorted[i].second, c = sorted[i + 1].second;
    if (pairOnly && parity(b.triangles[a]) != parity(b.triangles[c])) {
      drop[a] = drop[c] = 1;
      any = true;
    }
  }
  if (!any) return;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangleFace;
  std::set<int> kept;
  for (std::size_t t = 0; t < b.triangles.size(); ++t) {
    if (drop[t]) continue;
    triangles.push_back(b.triangles[t]);
    triangleFace.push_back(b.triangleFace[t]);
    kept.insert(b.triangleFace[t]);
  }
  std::vector<int> faces;
  for (const int f : b.faces) (kept.count(f) ? faces : b.internalFaces).push_back(f);
  std::sort(b.internalFaces.begin(), b.internalFaces.end());
  b.triangles = std::move(triangles);
  b.triangleFace = std::move(triangleFace);
  b.faces = std::move(faces);
}

}  // namespace

std::vector<std::vector<int>> trianglesByFace(const SurfaceMesh& mesh, int numFaces) {
  std::vector<std::vector<int>> out(static_cast<std::size_t>(std::max(0, numFaces)));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const int f = t < mesh.triangleFace.size() ? mesh.triangleFace[t] : -1;
    if (f >= 0 && f < numFaces) out[f].push_back(static_cast<int>(t));
  }
  return out;
}

double signedVolume(const SurfaceMesh& mesh, const std::vector<std::array<int, 3>>& triangles) {
  if (triangles.empty()) return 0;
  const Vec3 o = mesh.nodes[triangles.front()[0]];
  double v = 0;
  for (const auto& t : triangles) {
    const Vec3 a = mesh.nodes[t[0]] - o, b = mesh.nodes[t[1]] - o, c = mesh.nodes[t[2]] - o;
    v += a.dot(b.cross(c));
  }
  return v / 6.0;
}

BoundaryMesh buildBoundaryMesh(const Model& model, const SurfaceMesh& mesh,
                               const std::vector<std::vector<int>>& faceTriangles, int solid) {
  if (solid < 0 || solid >= static_cast<int>(model.solids.size()))
    throw InputError("buildBoundaryMesh: no solid " + std::to_string(solid + 1));
  const ModelSolid& ms = model.solids[solid];
  BoundaryMesh b;
  b.solid = solid;
  std::vector<int> shells{ms.outerShell};
  shells.insert(shells.end(), ms.voidShells.begin(), ms.voidShells.end());
  // Per face: +1 for each outward use in the mesh's direction, -1 for each reversed use.
  std::map<int, std::pair<int, int>> uses;  // face -> (same-direction uses, reversed uses)
  std::set<int> nodes;
  for (std::size_t k = 0; k < shells.size(); ++k) {
    const int s = shells[k];
    if (s < 0 || s >= static_cast<int>(model.shells.size()))
      throw InputError("solid " + std::to_string(solid + 1) + ": no shell " + std::to_string(s + 1));
    std::vector<OrientedFace> faces;
    std::vector<std::array<int, 3>> tris;
    for (const FaceUse& u : model.shells[s].faces) {
      if (u.face < 0 || u.face >= static_cast<int>(model.faces.size()) ||
          u.face >= static_cast<int>(faceTriangles.size()))
        continue;
      const bool flip = u.reversed != model.faces[u.face].reversed;
      faces.push_back({u.face, flip});
      for (const int t : faceTriangles[u.face]) {
        tris.push_back(oriented(mesh.triangles[t], flip));
        for (const int n : mesh.triangles[t]) nodes.insert(n);
      }
    }
    // Outer shell: positive volume; void shell: negative (normals into the void).
    const double v = signedVolume(mesh, tris);
    const bool wrong = k == 0 ? v < 0 : v > 0;
    if (wrong) b.flippedShells.push_back(s);
    for (const OrientedFace& f : faces) {
      auto& u = uses[f.face];
      (f.flip != wrong ? u.second : u.first) += 1;
    }
  }
  for (const auto& [f, u] : uses) {
    if (u.first > 0 && u.second > 0) {
      b.internalFaces.push_back(f);
      continue;
    }
    b.faces.push_back(f);
    const bool flip = u.second > 0;
    for (const int t : faceTriangles[f]) {
      b.triangles.push_back(oriented(mesh.triangles[t], flip));
      b.triangleFace.push_back(f);
    }
  }
  cancelOppositePairs(b);
  for (const EmbeddedFace& e : ms.embedded) {
    if (e.face < 0 || e.face >= static_cast<int>(faceTriangles.size()) || uses.count(e.face)) continue;
    for (const int t : faceTriangles[e.face]) {
      b.embedded.push_back(mesh.triangles[t]);
      b.embeddedFace.push_back(e.face);
      for (const int n : mesh.triangles[t]) nodes.insert(n);
    }
  }
  b.nodes.assign(nodes.begin(), nodes.end());
  return b;
}

std::vector<std::string> checkBoundaryMesh(const BoundaryMesh& b, const SurfaceMesh& mesh) {
  std::vector<std::string> problems;
  const std::string solid = "solid " + std::to_string(b.solid + 1);
  if (b.triangles.empty()) {
    problems.push_back(solid + ": no boundary triangles (its faces have no surface mesh)");
    return problems;
  }
  // Every directed use of an undirected edge (lo, hi), sorted by edge: forward when lo->hi.
  struct Use {
    int lo, hi, face;
    bool forward;
    bool operator<(const Use& o) const { return std::tie(lo, hi, face, forward) < std::tie(o.lo, o.hi, o.face, o.forward); }
  };
  std::vector<Use> uses;
  uses.reserve(3 * b.triangles.size());
  const int n = static_cast<int>(mesh.nodes.size());
  std::set<int> badIndexFaces;
  for (std::size_t t = 0; t < b.triangles.size(); ++t) {
    const auto& tri = b.triangles[t];
    if (std::any_of(tri.begin(), tri.end(), [&](int v) { return v < 0 || v >= n; })) {
      badIndexFaces.insert(b.triangleFace[t]);
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const int p = tri[k], q = tri[(k + 1) % 3];
      uses.push_back({std::min(p, q), std::max(p, q), b.triangleFace[t], p < q});
    }
  }
  std::sort(uses.begin(), uses.end());
  if (!badIndexFaces.empty())
    problems.push_back(solid + ": triangles with node indices out of range on faces " + faceList(badIndexFaces));
  std::set<int> openFaces, misFaces;
  long long open = 0, mis = 0;
  for (std::size_t i = 0, j = 0; i < uses.size(); i = j) {
    int forward = 0, backward = 0;
    for (j = i; j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi; ++j)
      (uses[j].forward ? forward : backward) += 1;
    std::set<int>* faces = nullptr;
    if (forward == 0 || backward == 0) {
      if (forward + backward == 1) ++open, faces = &openFaces;
      else ++mis, faces = &misFaces;
    } else if (forward != backward) {
      ++open, faces = &openFaces;
    }
    if (faces)
      for (std::size_t k = i; k < j; ++k) faces->insert(uses[k].face);
  }
  if (open)
    problems.push_back(solid + ": boundary mesh not closed: " + std::to_string(open) +
                       " edges used an odd number of times, on faces " + faceList(openFaces));
  if (mis)
    problems.push_back(solid + ": boundary mesh not consistently oriented: " + std::to_string(mis) +
                       " edges used twice in the same direction, on faces " + faceList(misFaces));
  if (problems.empty() && signedVolume(mesh, b.triangles) <= 0)
    problems.push_back(solid + ": boundary mesh encloses no positive volume");
  return problems;
}

}  // namespace aniso
