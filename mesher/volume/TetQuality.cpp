#include "mesher/volume/TetQuality.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "mesher/metric/MeanRatio.h"
#include "mesher/volume/improve/TetStar.h"

namespace aniso {
namespace {

constexpr double kRadToDeg = 57.29577951308232;

// Unit face normals as meshq.py builds them: faces (b,c,d), (a,c,d), (a,b,d), (a,b,c) with
// n = (y − x) × (z − x). For a positive tet n0 and n2 point outwards, n1 and n3 inwards.
void refereeNormals(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, Vec3 n[4]) {
  n[0] = (c - b).cross(d - b);
  n[1] = (c - a).cross(d - a);
  n[2] = (b - a).cross(d - a);
  n[3] = (b - a).cross(c - a);
  for (int i = 0; i < 4; ++i) n[i] /= std::max(n[i].norm(), 1e-300);
}

// Largest and smallest cosine of the 6 dihedral angles: −n_i·n_j with outward normals
// (`consistent`), or with meshq's normals as they are (`!consistent`).
void cosineRange(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, bool consistent, double& cmin,
                 double& cmax) {
  Vec3 n[4];
  refereeNormals(a, b, c, d, n);
  if (consistent) {
    const double s = (b - a).cross(c - a).dot(d - a) >= 0 ? 1.0 : -1.0;  // inverted: all flip
    n[0] *= s, n[1] *= -s, n[2] *= s, n[3] *= -s;
  }
  cmin = 1, cmax = -1;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const double cs = std::clamp(-n[i].dot(n[j]), -1.0, 1.0);
      cmin = std::min(cmin, cs);
      cmax = std::max(cmax, cs);
    }
}

}  // namespace

double tetMeanRatio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return meanRatio(a, b, c, d); }

DihedralRange tetDihedralRange(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  double cmin, cmax;
  cosineRange(a, b, c, d, true, cmin, cmax);
  return {std::acos(cmax) * kRadToDeg, std::acos(cmin) * kRadToDeg};
}

double tetMinDihedral(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  double cmin, cmax;
  cosineRange(a, b, c, d, true, cmin, cmax);
  return std::acos(cmax) * kRadToDeg;
}

double refereeMinDihedral(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  double cmin, cmax;
  cosineRange(a, b, c, d, false, cmin, cmax);
  return std::acos(cmax) * kRadToDeg;
}

void TetQualitySummary::merge(const TetQualitySummary& o) {
  tets += o.tets;
  inverted += o.inverted;
  volume += o.volume;
  meanRatio.merge(o.meanRatio);
  minDihedral = std::min(minDihedral, o.minDihedral);
  maxDihedral = std::max(maxDihedral, o.maxDihedral);
  belowDihedral += o.belowDihedral;
  refereeMinDihedral = std::min(refereeMinDihedral, o.refereeMinDihedral);
  etaM.merge(o.etaM);
  muM.merge(o.muM);
}

void accumulateTetQuality(const SolidTetMesh& s, const ControlSpace3d* cs, TetQualitySummary& out) {
  const del3d::TetMesh& mesh = s.mesh;
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k) {
    const del3d::TetId t(k);
    if (!mesh.isAlive(t)) continue;
    const std::uint32_t* tv = mesh.tetVertices(t);
    const Vec3 a = mesh.point(del3d::VertexId(tv[0])), b = mesh.point(del3d::VertexId(tv[1]));
    const Vec3 c = mesh.point(del3d::VertexId(tv[2])), d = mesh.point(del3d::VertexId(tv[3]));
    const double vol = (b - a).cross(c - a).dot(d - a) / 6.0;
    ++out.tets;
    out.volume += vol;
    if (vol <= 0) ++out.inverted;
    out.meanRatio.add(meanRatio(a, b, c, d));
    const DihedralRange r = tetDihedralRange(a, b, c, d);
    out.minDihedral = std::min(out.minDihedral, r.minDeg);
    out.maxDihedral = std::max(out.maxDihedral, r.maxDeg);
    if (r.minDeg < kSliverDihedralDeg) ++out.belowDihedral;
    out.refereeMinDihedral = std::min(out.refereeMinDihedral, refereeMinDihedral(a, b, c, d));
    if (cs) out.etaM.add(meanRatio(cs->getMetric(0.25 * (a + b + c + d)), a, b, c, d));
  }
  if (!cs) return;
  // μ_M: each edge once, from the star of its lower-index end.
  std::vector<del3d::TetId> star;
  std::vector<std::uint32_t> nbr;
  for (std::uint32_t v = 0; v < mesh.numVertices(); ++v) {
    const del3d::VertexId vid(v);
    if (!mesh.vertexTet(vid).valid()) continue;
    improve3d::vertexStar(mesh, vid, star);
    nbr.clear();
    for (const del3d::TetId t : star)
      for (int i = 0; i < 4; ++i)
        if (mesh.tetVertices(t)[i] > v) nbr.push_back(mesh.tetVertices(t)[i]);
    std::sort(nbr.begin(), nbr.end());
    nbr.erase(std::unique(nbr.begin(), nbr.end()), nbr.end());
    const Vec3 p = mesh.point(vid);
    for (const std::uint32_t w : nbr) {
      const Vec3 q = mesh.point(del3d::VertexId(w));
      out.muM.add(cs->getMetric(0.5 * (p + q)).length(q - p));
    }
  }
}

}  // namespace aniso
