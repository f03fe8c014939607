#include "mesher/delaunay3d/EnclosingBox.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/LU>

#include "mesher/core/Error.h"
#include "mesher/delaunay3d/TransformPoint.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::del3d {
namespace {

using Quad = std::array<int, 4>;

// The Delaunay tets (in metric coordinates `met`) of 8 points in convex position, by
// brute force over the 70 quadruples. Empty when some five points are cospherical (or
// four coplanar in a way that leaves ties): the caller perturbs and retries.
std::vector<Quad> delaunayOfCorners(const double (&phys)[8][3], const double (&met)[8][3]) {
  std::vector<Quad> tets;
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      for (int c = b + 1; c < 8; ++c)
        for (int d = c + 1; d < 8; ++d) {
          Quad q = {a, b, c, d};
          const double o = predicates::orient3d(phys[a], phys[b], phys[c], phys[d]);
          if (o == 0) continue;
          if (o < 0) std::swap(q[0], q[1]);
          const double s = predicates::orient3d(met[q[0]], met[q[1]], met[q[2]], met[q[3]]);
          if (s <= 0) return {};  // M turned a corner tet over: not a usable perturbation
          bool empty = true;
          for (int e = 0; e < 8 && empty; ++e) {
            if (e == a || e == b || e == c || e == d) continue;
            const double in = predicates::insphere(met[q[0]], met[q[1]], met[q[2]], met[q[3]], met[e]);
            if (in == 0) return {};
            empty = in < 0;
          }
          if (empty) tets.push_back(q);
        }
  // A triangulation of 8 points in convex position: 12 hull faces, the others twice.
  std::map<std::array<int, 3>, int> faces;
  for (const Quad& q : tets)
    for (int i = 0; i < 4; ++i) {
      std::array<int, 3> f = {q[kFaceVertex[i][0]], q[kFaceVertex[i][1]], q[kFaceVertex[i][2]]};
      std::sort(f.begin(), f.end());
      ++faces[f];
    }
  int hull = 0;
  for (const auto& [f, n] : faces) {
    if (n > 2) return {};
    hull += n == 1;
  }
  if (hull != 12) return {};
  return tets;
}

}  // namespace

EnclosingBox createEnclosingBox(TetMesh& mesh, const Box3& bounds, double margin, const Mat3* transform) {
  if (mesh.numTets() != 0) throw MeshingError("createEnclosingBox: the mesh already has tetrahedra");
  if (bounds.empty() || !bounds.lo.allFinite() || !bounds.hi.allFinite())
    throw MeshingError("createEnclosingBox: empty or non-finite bounds");
  if (!(margin > 0) || !std::isfinite(margin)) throw MeshingError("createEnclosingBox: margin must be > 0");
  const Mat3 m = transform ? *transform : Mat3::Identity();
  if (!m.allFinite() || !(m.determinant() > 0)) throw MeshingError("createEnclosingBox: det M must be > 0");
  const Mat3 minv = m.inverse();

  Box3 mb;  // metric-space bounds
  for (int c = 0; c < 8; ++c) {
    const Vec3 x((c & 1) ? bounds.hi.x() : bounds.lo.x(), (c & 2) ? bounds.hi.y() : bounds.lo.y(),
                 (c & 4) ? bounds.hi.z() : bounds.lo.z());
    mb.add(Vec3(m * x));
  }
  const double side = mb.size().maxCoeff();
  const double scale = std::max(mb.lo.cwiseAbs().maxCoeff(), mb.hi.cwiseAbs().maxCoeff());
  const double grow = margin * std::max(side, 1e-3 * (1.0 + scale));

  for (int attempt = 0; attempt < 16; ++attempt) {
    double phys[8][3], met[8][3];
    for (int c = 0; c < 8; ++c) {
      // Outward push, different per corner: no symmetric (cospherical) configuration.
      const double extra = grow * (1.0 + 0.061 * ((5 * c + 3 * attempt) % 8) + 0.013 * attempt);
      Vec3 q;
      for (int a = 0; a < 3; ++a) q[a] = ((c >> a) & 1) ? mb.hi[a] + extra : mb.lo[a] - extra;
      const Vec3 x = minv * q;
      for (int a = 0; a < 3; ++a) phys[c][a] = x[a];
      transformPoint(m, phys[c], met[c]);
    }
    const std::vector<Quad> tets = delaunayOfCorners(phys, met);
    if (tets.empty()) continue;

    EnclosingBox eb;
    for (int c = 0; c < 8; ++c) {
      eb.corners[c] = mesh.addVertex(Vec3(phys[c][0], phys[c][1], phys[c][2]));
      eb.box.add(mesh.point(eb.corners[c]));
    }
    std::vector<TetId> ids;
    for (const Quad& q : tets) {
      ids.push_back(mesh.createTet(eb.corners[q[0]], eb.corners[q[1]], eb.corners[q[2]], eb.corners[q[3]]));
      for (const int c : q) mesh.setVertexTet(eb.corners[c], ids.back());
    }
    std::map<std::array<std::uint32_t, 3>, std::uint32_t> open;  // face -> code
    for (const TetId t : ids)
      for (int i = 0; i < 4; ++i) {
        const std::uint32_t* v = mesh.tetVertices(t);
        std::array<std::uint32_t, 3> f = {v[kFaceVertex[i][0]], v[kFaceVertex[i][1]], v[kFaceVertex[i][2]]};
        std::sort(f.begin(), f.end());
        const auto it = open.find(f);
        if (it == open.end()) {
          open.emplace(f, faceCode(t, i));
        } else {
          mesh.link(t, i, codeTet(it->second), codeFace(it->second));
          open.erase(it);
        }
      }
    mesh.setCertifiedDelaunay(transform == nullptr || m.isIdentity(0.0));
    return eb;
  }
  throw MeshingError("createEnclosingBox: no non-degenerate box corners found");
}

}  // namespace aniso::del3d
