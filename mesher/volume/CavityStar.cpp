#include "mesher/volume/CavityStar.h"

#include <algorithm>

#include <Eigen/Geometry>

#include "mesher/predicates/Predicates.h"

namespace aniso::volume {

using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

namespace {

/// A star is taken from an existing vertex without looking further when its worst tet has
/// at least this shape measure (volume / longest edge^3; 0.118 for the regular tet).
constexpr double kGoodVertexStar = 0.01;
/// Offsets of the candidate new points from the patch, in units of its mean edge length.
constexpr double kOffsets[] = {0.1, 0.25, 0.5, 1.0, 0.05};
/// Margins (in units of the patch's mean edge length) of the kernel points sought.
constexpr double kKernelMargins[] = {0.05, 0.01, 1e-3, 1e-5, 1e-7};
/// Relaxation steps of relaxIntoKernel (a kernel that is not reached by then is empty or
/// too thin for the margin; the profile of ellipses.brep showed the solver spending half
/// of the recovery time in vain relaxations at 2000).
constexpr int kRelaxIterations = 500;

double vol6(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return (b - a).dot((c - a).cross(d - a)); }

/// Worst shape of the star of `p` over `faces`: negative when a tet is not positively
/// oriented (exact test). Faces containing `skip` (the apex when it is a vertex) are left out.
/// `first` (in/out) is the face tested first, set to the one that rejected `p`: candidates
/// near each other are usually rejected by the same face, and the result does not depend on
/// the order.
double starShape(const TetMesh& m, const std::vector<CavityFace>& faces, const double* p, VertexId skip,
                 std::size_t& first) {
  const auto visible = [&](const CavityFace& f) {
    return f[0] == skip || f[1] == skip || f[2] == skip ||
           predicates::orient3d(m.coords(f[0]), m.coords(f[1]), m.coords(f[2]), p) > 0;
  };
  if (first < faces.size() && !visible(faces[first])) return -1;
  double worst = 1e300;
  const Vec3 pv(p[0], p[1], p[2]);
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const CavityFace& f = faces[k];
    if (f[0] == skip || f[1] == skip || f[2] == skip) continue;
    if (!visible(f)) {
      first = k;
      return -1;
    }
    const Vec3 a = m.point(f[0]), b = m.point(f[1]), c = m.point(f[2]);
    const double l = std::max({(a - b).norm(), (b - c).norm(), (c - a).norm(), (pv - a).norm(), (pv - b).norm(),
                               (pv - c).norm()});
    worst = std::min(worst, vol6(a, b, c, pv) / 6.0 / (l * l * l));
  }
  return worst;
}

}  // namespace

bool patchFrame(const TetMesh& m, const std::vector<CavityFace>& tris, const std::vector<int>& patch, PatchFrame& out) {
  Vec3 normal(0, 0, 0), centroid(0, 0, 0);
  double area = 0, edgeSum = 0;
  for (const int t : patch) {
    const Vec3 a = m.point(tris[t][0]), b = m.point(tris[t][1]), c = m.point(tris[t][2]);
    const Vec3 n = (b - a).cross(c - a);
    normal += n;
    area += 0.5 * n.norm();
    centroid += 0.5 * n.norm() * (a + b + c) / 3.0;
    edgeSum += (a - b).norm() + (b - c).norm() + (c - a).norm();
  }
  if (!(area > 0) || !(normal.norm() > 0)) return false;
  out.normal = normal.normalized();
  out.centroid = centroid / area;
  out.h = edgeSum / (3.0 * static_cast<double>(patch.size()));
  return true;
}

bool KernelFaces::build(const TetMesh& m, const std::vector<CavityFace>& faces) {
  nx.clear(), ny.clear(), nz.clear(), offset.clear();
  for (const CavityFace& f : faces) {
    const Vec3 a = m.point(f[0]), b = m.point(f[1]), c = m.point(f[2]);
    Vec3 n = (b - a).cross(c - a);  // points into the polyhedron (faces are oriented so)
    const double len = n.norm();
    if (!(len > 0)) return false;
    n /= len;
    nx.push_back(n.x()), ny.push_back(n.y()), nz.push_back(n.z());
    offset.push_back(n.dot(a));
  }
  return true;
}

bool KernelFaces::relax(Vec3 start, double margin, Vec3& out) const {
  Vec3 p = start;
  const std::size_t nf = offset.size();
  for (int it = 0; it < kRelaxIterations; ++it) {
    double worst = margin;
    std::size_t wf = nf;
    for (std::size_t f = 0; f < nf; ++f) {
      const double d = Vec3(nx[f], ny[f], nz[f]).dot(p) - offset[f];
      if (d < worst) {
        worst = d;
        wf = f;
      }
    }
    if (wf == nf) {
      out = p;
      return true;
    }
    p += (margin - worst) * Vec3(nx[wf], ny[wf], nz[wf]);
  }
  out = p;
  return false;
}

bool relaxIntoKernel(const TetMesh& m, const std::vector<CavityFace>& faces, Vec3 start, double margin, Vec3& out) {
  KernelFaces k;
  return k.build(m, faces) && k.relax(start, margin, out);
}

std::vector<Vec3> apexCandidates(const TetMesh& m, const std::vector<CavityFace>& side, const std::vector<TetId>& cavity,
                                 const PatchFrame& frame, double direction) {
  std::vector<Vec3> c;
  for (const double s : kOffsets) c.push_back(frame.centroid + direction * s * frame.h * frame.normal);
  Vec3 mean(0, 0, 0);
  std::set<std::uint32_t> vs;
  for (const CavityFace& f : side)
    for (const VertexId v : f)
      if (vs.insert(v.index).second) mean += m.point(v);
  mean /= static_cast<double>(vs.size());
  c.push_back(mean);
  c.push_back(0.5 * (mean + frame.centroid));
  for (const TetId t : cavity) {  // the centroids of the cavity's tets
    Vec3 g(0, 0, 0);
    for (int k = 0; k < 4; ++k) g += 0.25 * m.point(m.vertex(t, k));
    c.push_back(g);
  }
  // A point of the kernel: the widest margin found. The narrowest is tried first: when even
  // it is not reached the kernel is empty (or too thin), and the wider ones are not tried
  // (each vain relaxation runs kRelaxIterations steps over every face).
  KernelFaces kernel;
  const Vec3 start = frame.centroid + direction * 0.25 * frame.h * frame.normal;
  Vec3 k;
  const double narrowest = kKernelMargins[std::size(kKernelMargins) - 1];
  if (!kernel.build(m, side) || !kernel.relax(start, narrowest * frame.h, k)) return c;
  for (const double margin : kKernelMargins)
    if (kernel.relax(start, margin * frame.h, k)) {
      c.push_back(k);
      break;
    }
  return c;
}

Apex chooseApex(const TetMesh& m, const std::vector<CavityFace>& faces, const std::vector<Vec3>& candidates,
                const std::set<std::uint32_t>& forbidden) {
  std::set<std::uint32_t> verts;
  for (const CavityFace& f : faces)
    for (const VertexId v : f)
      if (!forbidden.count(v.index)) verts.insert(v.index);
  Apex bestVertex;
  double bestVertexShape = 0;
  std::size_t first = faces.size();
  for (const std::uint32_t v : verts) {
    const double s = starShape(m, faces, m.coords(VertexId(v)), VertexId(v), first);
    if (s > bestVertexShape) {
      bestVertexShape = s;
      bestVertex = {true, false, VertexId(v), m.point(VertexId(v))};
    }
  }
  if (bestVertex.found && bestVertexShape >= kGoodVertexStar) return bestVertex;
  Apex bestNew;
  double bestNewShape = 0;
  for (const Vec3& c : candidates) {
    if (!c.allFinite()) continue;
    const double s = starShape(m, faces, c.data(), VertexId(), first);
    if (s > bestNewShape) {
      bestNewShape = s;
      bestNew = {true, true, VertexId(), c};
    }
  }
  if (bestNew.found && bestNewShape > bestVertexShape) return bestNew;
  return bestVertex;
}

}  // namespace aniso::volume
